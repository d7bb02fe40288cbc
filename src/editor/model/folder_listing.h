#pragma once
#include <string>
#include <vector>

#include "core/result.h"

namespace kinema {

// What the file dialog shows of one folder: its subfolders, then the files whose
// extension is one of `extensions` (lower case with the dot, ".bvh"; empty = all files),
// each group sorted by name. Hidden entries (leading '.') are left out.
struct FolderEntry {
  std::string name;
  bool isFolder = false;
};
struct FolderListing {
  std::string folder;  // the absolute, normalised folder that was listed
  std::vector<FolderEntry> entries;
};

Result<FolderListing> listFolder(const std::string& folder, const std::vector<std::string>& extensions);

// The extensions the editor opens, and those it saves / exports (lower case, with the dot).
const std::vector<std::string>& openableExtensions();

// `path` with `extension` appended unless it already ends with it (case-insensitive), so
// "walk" saved as .kinema becomes "walk.kinema".
std::string withExtension(const std::string& path, const std::string& extension);

}  // namespace kinema
