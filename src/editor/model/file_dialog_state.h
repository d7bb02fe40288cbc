#pragma once
#include <string>
#include <vector>

#include "editor/model/folder_listing.h"

namespace kinema {

// The editor's own file dialog (ImGui 1.86 has none): a path field, the current folder's
// listing filtered by the extensions the purpose accepts, and the recent files.
enum class FileDialogPurpose { Open, SaveAs, ExportGltf, ExportGlb, ExportBvh };

struct FileDialogState {
  bool visible = false;
  bool justOpened = false;  // OpenPopup on the next draw
  FileDialogPurpose purpose = FileDialogPurpose::Open;
  std::string folder;       // the folder listed
  char path[1024] = {};     // what the path field holds (a name relative to `folder`, or absolute)
  FolderListing listing;
  std::string listingError;
  std::string confirmOverwrite;  // a save target that exists: asked about before it is chosen
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

// The path the field names: absolute as typed, else relative to the listed folder, with the
// purpose's extension appended for saves when it has none.
std::string resolveDialogPath(const FileDialogState& dialog);

}  // namespace kinema
