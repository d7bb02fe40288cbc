#pragma once
#include <string>
#include <vector>

#include "editor/model/folder_listing.h"
#include "io/up_axis.h"

namespace kinema {

// The editor's own file dialog (ImGui 1.86 has none): a path field, the current folder's
// listing filtered by the extensions the purpose accepts, and the recent files.
// ImportMotion reads a motion file for File > Import Motion onto Character… (motion_import.h).
enum class FileDialogPurpose { Open, SaveAs, ExportGltf, ExportGlb, ExportBvh, ImportMotion };

struct FileDialogState {
  bool visible = false;
  bool justOpened = false;  // OpenPopup on the next draw
  FileDialogPurpose purpose = FileDialogPurpose::Open;
  std::string folder;       // the folder listed
  char path[1024] = {};     // what the path field holds (a name relative to `folder`, or absolute)
  FolderListing listing;
  std::string listingError;
  std::string confirmOverwrite;  // a save target that exists: asked about before it is chosen
  // Open and ImportMotion: the up axis a .bvh file is read with (shown when the field names one; Y is the
  // BVH convention, Z what Blender's BVH exporter writes). Kept between openings.
  UpAxis bvhUp = UpAxis::Y;
};

const char* fileDialogTitle(FileDialogPurpose purpose);
// The extensions listed for a purpose; the first one is appended to a typed name without one.
std::vector<std::string> fileDialogExtensions(FileDialogPurpose purpose);

// Shows the dialog; `startPath` preselects a folder and name (the document's path).
void openFileDialog(FileDialogState& dialog, FileDialogPurpose purpose, const std::string& startPath);
// Whether the purpose writes a file (Save As, the exports): those ask before replacing one.
bool isSaveDialog(FileDialogPurpose purpose);
// Lists `folder` for the dialog's purpose (the error lands in listingError, the old listing stays).
void relistFileDialog(FileDialogState& dialog, const std::string& folder);
// Puts `text` into the path field (cut to the field's size).
void setFileDialogField(FileDialogState& dialog, const std::string& text);

// Whether the dialog offers the BVH up-axis choice: Open or ImportMotion, with a .bvh name in the field.
bool showsBvhUpAxis(const FileDialogState& dialog);

// The path the field names: absolute as typed, else relative to the listed folder, with the
// purpose's extension appended for saves when it has none.
std::string resolveDialogPath(const FileDialogState& dialog);

}  // namespace kinema
