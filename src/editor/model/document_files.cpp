#include "editor/model/document_files.h"

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "scene/default_character_scene.h"
#include "io/atomic_write.h"
#include "io/bvh_writer.h"
#include "io/gltf_writer.h"
#include "io/kinema_file.h"
#include "io/text_file.h"
#include "io/scene_files.h"

namespace kinema {

namespace fs = std::filesystem;

Document newDocument() {
  // The same scene as cli/command_line.cpp's loadSceneOrDefault(""): the skinned body.
  return Document(makeDefaultCharacterScene());
}

Result<Document> openDocument(const std::string& path, const InputLimits& limits, UpAxis bvhUp) {
  Result<Scene> scene = loadScene(path, limits, bvhUp);
  if (!scene) return Result<Document>::failure(scene.error());
  return Document(std::move(scene).value(), path);
}

bool canSaveInPlace(const Document& doc) { return !doc.path().empty() && lowerExtension(doc.path()) == ".kinema"; }

std::string saveDocument(Document& doc) {
  if (doc.path().empty()) return "the document has no file yet: use Save As";
  if (!canSaveInPlace(doc)) return doc.path() + ": not a .kinema file: use Save As (or Export to keep the format)";
  return saveDocumentAs(doc, doc.path());
}

std::string saveDocumentAs(Document& doc, const std::string& path) {
  if (path.empty()) return "no file name given";
  if (lowerExtension(path) != ".kinema")
    return path + ": projects are saved as .kinema; use Export for .gltf, .glb or .bvh";
  if (doc.dragging()) return "finish the current drag before saving";
  const std::string error = saveKinemaFile(path, doc.sceneForSaving());
  if (!error.empty()) return error;
  doc.setPath(path);
  doc.markSaved();
  return {};
}

namespace {

// The working pose as a clip of one key at time 0 (every joint's T, R and S).
Clip poseClip(const Skeleton& skeleton, const Pose& pose) {
  Clip clip;
  clip.name = "pose";
  for (int j = 0; j < skeleton.size(); ++j) {
    const Transform& t = pose.local[j];
    clip.channels.emplace_back(j, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{0.0f},
                               std::vector<glm::vec4>{glm::vec4(t.translation, 0.0f)});
    clip.channels.emplace_back(j, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{0.0f},
                               std::vector<glm::vec4>{glm::vec4(t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w)});
    clip.channels.emplace_back(j, ChannelTarget::Scale, Interpolation::Linear, std::vector<float>{0.0f},
                               std::vector<glm::vec4>{glm::vec4(t.scale, 0.0f)});
  }
  return clip;
}

}  // namespace

std::string exportDocument(const Document& doc, const std::string& path, std::vector<std::string>* report,
                           int bvhClip) {
  const std::string ext = lowerExtension(path);
  if (ext != ".gltf" && ext != ".glb" && ext != ".bvh")
    return path + ": export writes .gltf, .glb or .bvh (save .kinema with Save As)";
  Scene scene = doc.sceneForSaving();
  // glTF and BVH have no place for a pose beside the rest pose and the clips: when the
  // scene has no clips, the working pose goes out as a one-key clip; a scene with clips
  // exports its clips and the working pose is not written (the report says so).
  if (scene.clips.empty()) {
    scene.clips.push_back(poseClip(scene.skeleton, scene.pose));
  } else if (report) {
    report->push_back("the working pose is not exported: the scene's clips are");
  }
  try {
    if (bvhClip < 0) bvhClip = doc.activeClip();
    if (bvhClip >= static_cast<int>(scene.clips.size())) bvhClip = 0;
    SceneSaveOptions options;  // saveScene reports what the format drops (BVH: the other clips, meshes)
    options.bvhClip = bvhClip;
    return saveScene(path, scene, options, report);
  } catch (const std::exception& e) {
    return path + ": not exported: " + e.what();
  }
}

std::string documentTitle(const Document& doc) {
  const std::string name = doc.path().empty() ? "untitled" : fs::path(doc.path()).filename().string();
  return name + (doc.dirty() ? "*" : "") + " - Kinema";
}

std::string kinemaConfigDir() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/kinema";
  const char* home = std::getenv("HOME");
  if (home && home[0]) return std::string(home) + "/.config/kinema";
  return {};
}

RecentFiles::RecentFiles(std::string file) : file_(std::move(file)) {}

std::string RecentFiles::defaultFile() {
  const std::string dir = kinemaConfigDir();
  return dir.empty() ? std::string() : dir + "/recent.json";
}

std::string RecentFiles::load() {
  entries_.clear();
  if (file_.empty()) return "no config folder (neither XDG_CONFIG_HOME nor HOME is set): recent files are not kept";
  std::error_code ec;
  if (!fs::exists(file_, ec)) return {};
  std::string text;
  std::string error = readTextFile(file_, text, 1 << 20);
  if (!error.empty()) return error + " (recent files ignored)";
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) return file_ + ": not valid JSON (recent files ignored)";
  if (!j.is_object() || !j.contains("recent") || !j["recent"].is_array())
    return file_ + ": recent: expected an array of paths (recent files ignored)";
  for (size_t i = 0; i < j["recent"].size(); ++i) {
    const nlohmann::json& p = j["recent"][i];
    if (!p.is_string() || p.get<std::string>().empty()) {
      entries_.clear();
      return file_ + ": recent[" + std::to_string(i) + "]: expected a path string (recent files ignored)";
    }
    if (static_cast<int>(entries_.size()) < kMaxEntries) entries_.push_back(p.get<std::string>());
  }
  return {};
}

std::string RecentFiles::save() const {
  if (file_.empty()) return "no config folder (neither XDG_CONFIG_HOME nor HOME is set)";
  std::error_code ec;
  const fs::path parent = fs::path(file_).parent_path();
  if (!parent.empty()) fs::create_directories(parent, ec);
  if (ec) return parent.string() + ": cannot create the folder: " + ec.message();
  nlohmann::json j;
  j["recent"] = entries_;
  try {
    return writeFileAtomically(file_, j.dump(1) + "\n");
  } catch (const std::exception& e) {  // invalid UTF-8 in a path
    return file_ + ": not saved: " + e.what();
  }
}

void RecentFiles::add(const std::string& path) {
  if (path.empty()) return;
  remove(path);
  entries_.insert(entries_.begin(), path);
  if (static_cast<int>(entries_.size()) > kMaxEntries) entries_.resize(kMaxEntries);
}

void RecentFiles::remove(const std::string& path) {
  for (size_t i = 0; i < entries_.size();)
    if (entries_[i] == path)
      entries_.erase(entries_.begin() + static_cast<long>(i));
    else
      ++i;
}

}  // namespace kinema
