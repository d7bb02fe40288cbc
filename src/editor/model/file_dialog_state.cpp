// The file dialog's state (no ImGui): Open lists .kinema/.bvh/.gltf/.glb, the save purposes list their own
// extension and ask before replacing an existing file.
#include "editor/model/file_dialog_state.h"

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io/scene_files.h"

namespace kinema {

namespace fs = std::filesystem;

void setFileDialogField(FileDialogState& d, const std::string& text) {
  std::snprintf(d.path, sizeof(d.path), "%s", text.c_str());
}

bool isSaveDialog(FileDialogPurpose p) { return p != FileDialogPurpose::Open && p != FileDialogPurpose::ImportMotion; }

bool showsBvhUpAxis(const FileDialogState& d) {
  return !isSaveDialog(d.purpose) && lowerExtension(d.path) == ".bvh";
}

void relistFileDialog(FileDialogState& d, const std::string& folder) {
  Result<FolderListing> listing = listFolder(folder, fileDialogExtensions(d.purpose));
  if (!listing) {
    d.listingError = listing.error();
    return;
  }
  d.listingError.clear();
  d.listing = std::move(listing.value());
  d.folder = d.listing.folder;
}

const char* fileDialogTitle(FileDialogPurpose purpose) {
  switch (purpose) {
    case FileDialogPurpose::Open: return "Open";
    case FileDialogPurpose::SaveAs: return "Save As";
    case FileDialogPurpose::ExportGltf: return "Export glTF";
    case FileDialogPurpose::ExportGlb: return "Export GLB";
    case FileDialogPurpose::ExportBvh: return "Export BVH";
    case FileDialogPurpose::ImportMotion: return "Import Motion File";
  }
  return "File";
}

std::vector<std::string> fileDialogExtensions(FileDialogPurpose purpose) {
  switch (purpose) {
    case FileDialogPurpose::Open: return openableExtensions();
    case FileDialogPurpose::SaveAs: return {".kinema"};
    case FileDialogPurpose::ExportGltf: return {".gltf"};
    case FileDialogPurpose::ExportGlb: return {".glb"};
    case FileDialogPurpose::ExportBvh: return {".bvh"};
    case FileDialogPurpose::ImportMotion: return openableExtensions();
  }
  return {};
}

std::string resolveDialogPath(const FileDialogState& d) {
  std::string typed(d.path);
  if (typed.empty()) return {};
  if (typed.size() >= 2 && typed[0] == '~' && typed[1] == '/') {
    if (const char* home = std::getenv("HOME")) typed = std::string(home) + typed.substr(1);
  }
  fs::path p(typed);
  if (p.is_relative()) p = fs::path(d.folder.empty() ? "." : d.folder) / p;
  std::string resolved = p.lexically_normal().string();
  if (isSaveDialog(d.purpose)) resolved = withExtension(resolved, fileDialogExtensions(d.purpose).front());
  return resolved;
}

void openFileDialog(FileDialogState& d, FileDialogPurpose purpose, const std::string& startPath) {
  d.visible = true;
  d.justOpened = true;
  d.purpose = purpose;
  d.confirmOverwrite.clear();
  std::string folder = ".", name;
  if (!startPath.empty()) {
    const fs::path p(startPath);
    if (p.has_parent_path()) folder = p.parent_path().string();
    name = p.filename().string();
    // A save purpose proposes the document's name with the purpose's extension.
    if (isSaveDialog(purpose)) name = p.stem().string() + fileDialogExtensions(purpose).front();
    else name.clear();
  }
  relistFileDialog(d, folder);
  if (!d.listingError.empty()) relistFileDialog(d, ".");
  setFileDialogField(d, name);
}

}  // namespace kinema
