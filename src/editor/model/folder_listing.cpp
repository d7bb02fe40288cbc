#include "editor/model/folder_listing.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "io/scene_files.h"

namespace kinema {

namespace fs = std::filesystem;

const std::vector<std::string>& openableExtensions() {
  static const std::vector<std::string> extensions{".kinema", ".bvh", ".gltf", ".glb"};
  return extensions;
}

std::string withExtension(const std::string& path, const std::string& extension) {
  if (path.empty() || lowerExtension(path) == extension) return path;
  return path + extension;
}

Result<FolderListing> listFolder(const std::string& folder, const std::vector<std::string>& extensions) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(folder.empty() ? fs::path(".") : fs::path(folder), ec).lexically_normal();
  if (ec) return Result<FolderListing>::failure(folder + ": " + ec.message());
  if (!fs::is_directory(absolute, ec))
    return Result<FolderListing>::failure(absolute.string() + ": not a folder");
  FolderListing listing;
  listing.folder = absolute.string();
  if (listing.folder.size() > 1 && listing.folder.back() == '/') listing.folder.pop_back();
  fs::directory_iterator it(absolute, fs::directory_options::skip_permission_denied, ec);
  if (ec) return Result<FolderListing>::failure(listing.folder + ": " + ec.message());
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) return Result<FolderListing>::failure(listing.folder + ": " + ec.message());
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code typeError;
    const bool isFolder = it->is_directory(typeError);
    if (!isFolder) {
      const std::string ext = lowerExtension(name);
      if (!extensions.empty() && std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) continue;
    }
    listing.entries.push_back({name, isFolder});
  }
  std::sort(listing.entries.begin(), listing.entries.end(), [](const FolderEntry& a, const FolderEntry& b) {
    return a.isFolder != b.isFolder ? a.isFolder : a.name < b.name;
  });
  return listing;
}

}  // namespace kinema
