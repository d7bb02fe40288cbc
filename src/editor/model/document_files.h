#pragma once
#include <string>
#include <vector>

#include "core/result.h"
#include "editor/model/document.h"
#include "io/scene_files.h"

namespace kinema {

// New / open / save / save as / export. Errors are one-line strings for the UI; nothing
// here throws.

// The default character (what `kinema` shows without a file; cli's loadSceneOrDefault).
Document newDocument();
// .kinema, .gltf, .glb or .bvh (io/scene.h loadScene); the pose saved in a .kinema file
// becomes the working pose.
// A .bvh file is read as `bvhUp`-up (the open dialog's choice; io/up_axis.h).
Result<Document> openDocument(const std::string& path, const InputLimits& limits = {},
                              UpAxis bvhUp = UpAxis::Y);
// Ctrl+S: to the document's own path; needs Save As when it has none or is not .kinema.
bool canSaveInPlace(const Document& doc);
std::string saveDocument(Document& doc);
// Save As: writes a .kinema file (atomically), then the document takes the new path and
// is clean.
std::string saveDocumentAs(Document& doc, const std::string& path);
// Export to .gltf, .glb or .bvh through the io writers. The document keeps its path and
// dirty flag. `report` receives what the format could not hold.
// glTF writes every clip, in file order. BVH holds one clip: `bvhClip`, by default (-1) the
// active one (Document::activeClip); when the scene has more, `report` says which went out.
std::string exportDocument(const Document& doc, const std::string& path, std::vector<std::string>* report = nullptr,
                           int bvhClip = -1);

// The window title: the file's name (or "untitled"), a "*" when dirty, then " - Kinema".
std::string documentTitle(const Document& doc);

// $XDG_CONFIG_HOME/kinema (or ~/.config/kinema); "" when neither is known.
std::string kinemaConfigDir();

// The recent-files list, newest first, at most kMaxEntries, persisted as JSON
// {"recent": ["path", ...]} in kinemaConfigDir()/recent.json.
class RecentFiles {
 public:
  static constexpr int kMaxEntries = 10;
  explicit RecentFiles(std::string file = defaultFile());
  static std::string defaultFile();

  // Reads the file; a missing file is an empty list, a corrupt one is ignored (empty
  // list) and the returned message says why. "" when all is well.
  std::string load();
  // Writes the list (creating missing folders). "" or the error.
  std::string save() const;
  // Moves `path` to the front (no duplicates), dropping the oldest beyond kMaxEntries.
  void add(const std::string& path);
  void remove(const std::string& path);
  const std::vector<std::string>& entries() const { return entries_; }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::vector<std::string> entries_;
};

}  // namespace kinema
