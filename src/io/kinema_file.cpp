#include "io/kinema_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/atomic_write.h"
#include "io/image.h"
#include "io/json_document.h"
#include "io/kinema_file_sections.h"
#include "io/message_text.h"
#include "io/text_file.h"

// The whole file: the format and version check, then each section in its own file
// (io/kinema_file_sections.h); the playhead and the frame rate, one value each, are here.
namespace kinema {

using kinema_format::Json;
using kinema_format::Reader;

namespace {

// Puts arrays that hold only numbers on one line: "[0.0, 0.95, 0.0]" instead of one
// number per line, which keeps clips readable and files a third the size.
std::string collapseNumberArrays(const std::string& in) {
  std::string out;
  out.reserve(in.size());
  bool inString = false;
  for (size_t i = 0; i < in.size(); ++i) {
    if (inString || in[i] == '"') {
      // Copy strings verbatim: a joint may be called "arm[ 1 ]".
      if (inString && in[i] == '\\') {
        out += in[i++];
      } else if (in[i] == '"') {
        inString = !inString;
      }
      out += in[i];
      continue;
    }
    if (in[i] != '[') {
      out += in[i];
      continue;
    }
    size_t end = i + 1;
    while (end < in.size() && in[end] != ']' && in[end] != '[' && in[end] != '{' && in[end] != '"') ++end;
    if (end >= in.size() || in[end] != ']') {
      out += in[i];
      continue;
    }
    out += '[';
    bool space = false;
    for (size_t k = i + 1; k < end; ++k) {
      const char c = in[k];
      if (c == '\n' || c == '\t' || c == ' ') {
        space = true;
        continue;
      }
      if (space && out.back() == ',') out += ' ';
      space = false;
      out += c;
    }
    out += ']';
    i = end;
  }
  return out;
}

// ---- the editor's playhead (optional top-level "playhead" key) ----
// {"clip": INDEX, "time": SECONDS}: the clip must exist (0 when the file has none), the
// time be finite.
bool readPlayhead(Reader& r, const Json& root, Scene& scene) {
  const Json* object = r.member(root, "", "playhead", false);
  if (!object) return true;
  if (!object->is_object()) return r.fail("playhead", "expected an object");
  ScenePlayhead playhead;
  long long clip = 0;
  const Json* v;
  if (!(v = r.member(*object, "playhead", "clip", true)) || !r.integer(*v, "playhead.clip", clip)) return false;
  const long long clips = static_cast<long long>(scene.clips.size());
  if (clip < 0 || (clip >= clips && clip != 0))
    return r.fail("playhead.clip", std::to_string(clip) + " is not a clip of the file (it has " + std::to_string(clips) + ")");
  playhead.clip = static_cast<int>(clip);
  if (!(v = r.member(*object, "playhead", "time", true)) || !r.number(*v, "playhead.time", playhead.time)) return false;
  scene.playhead = playhead;
  return true;
}

// ---- the document's frame rate (optional top-level "frame_rate" key) ----
// Frames per second, kMinFrameRate..kMaxFrameRate; absent: kDefaultFrameRate.
bool readFrameRate(Reader& r, const Json& root, Scene& scene) {
  const Json* v = r.member(root, "", "frame_rate", false);
  if (!v) return true;
  double rate = 0.0;
  if (!r.number(*v, "frame_rate", rate)) return false;
  if (!(rate >= kMinFrameRate && rate <= kMaxFrameRate)) return r.fail("frame_rate", "must be 1 to 1000 frames per second");
  scene.frameRate = rate;
  return true;
}

}  // namespace

std::string toKinemaJson(const Scene& scene) {
  using namespace kinema_format;
  Json root;
  root["format"] = "kinema";
  root["version"] = kKinemaFormatVersion;
  root["skeleton"] = skeletonToJson(scene.skeleton);
  root["clips"] = clipsToJson(scene);
  // Optional: written when it is not the default, so files of other rates keep theirs.
  if (scene.frameRate != kDefaultFrameRate) root["frame_rate"] = scene.frameRate;
  // Optional: the editor's working pose; files without one load as the rest pose.
  if (!scene.pose.local.empty()) root["pose"] = poseToJson(scene);
  // Optional: where the timeline stood; the time as a double, which JSON keeps exactly.
  if (scene.playhead) root["playhead"] = {{"clip", scene.playhead->clip}, {"time", scene.playhead->time}};
  if (!scene.ik.empty()) root["ik"] = ikToJson(scene);  // optional: files without IK data stay as they were
  if (!scene.simulation.empty()) root["simulation"] = simulationToJson(scene);  // optional, as "ik"
  sceneAssetsToJson(scene, root);  // optional too: only scenes with meshes (glTF) have them
  return collapseNumberArrays(root.dump(1, '\t')) + "\n";
}

namespace {

// The scene in a parsed .kinema tree; `inputBytes` (the file's size) sets its image budget.
Result<Scene> readKinemaTree(const Json& root, const std::string& source, const InputLimits& limits, size_t inputBytes) {
  using namespace kinema_format;
  Reader r(source, limits, inputBytes);
  if (!root.is_object()) return Result<Scene>::failure(source + ": expected a JSON object at the top");
  std::string format;
  const Json* v;
  if (!(v = r.member(root, "", "format", true)) || !r.string(*v, "format", format))
    return Result<Scene>::failure(r.error());
  if (format != "kinema")
    return Result<Scene>::failure(oneLineMessage(source + ": format: expected \"kinema\", found \"" + cutForMessage(format) + "\""));
  long long version = 0;
  if (!(v = r.member(root, "", "version", true)) || !r.integer(*v, "version", version))
    return Result<Scene>::failure(r.error());
  if (version > kKinemaFormatVersion)
    return Result<Scene>::failure(oneLineMessage(source + ": version: the file is version " + std::to_string(version) +
                                          ", newer than this Kinema reads (up to version " +
                                          std::to_string(kKinemaFormatVersion) + "); update Kinema to open it"));
  if (version < 1)
    return Result<Scene>::failure(oneLineMessage(source + ": version: " + std::to_string(version) +
                                          " is not a Kinema format version (they start at 1)"));
  Scene scene;
  scene.source = source;
  if (!readSkeleton(r, root, scene.skeleton) || !readClips(r, root, scene))
    return Result<Scene>::failure(r.error());
  if (!readIk(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readSimulation(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readPose(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readPlayhead(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readFrameRate(r, root, scene)) return Result<Scene>::failure(r.error());
  if (!readSceneAssets(r, root, scene)) return Result<Scene>::failure(r.error());
  const std::string bad = scene.skeleton.validate();
  if (!bad.empty()) return Result<Scene>::failure(oneLineMessage(source + ": skeleton: " + bad));
  return scene;
}

}  // namespace

Result<Scene> parseKinemaJson(const std::string& text, const std::string& source, const InputLimits& limits) {
  Json root;
  if (std::string e = parseJsonDocument(text, source, limits, root); !e.empty()) return Result<Scene>::failure(e);
  return readKinemaTree(root, source, limits, text.size());
}

Result<IkRig> parseIkRigJson(const std::string& text, const std::string& source, const Skeleton& skeleton) {
  const InputLimits limits;
  Json root;
  if (std::string e = parseJsonDocument(text, source, limits, root); !e.empty()) return Result<IkRig>::failure(e);
  Reader r(source);
  Scene scene;
  scene.skeleton = skeleton;
  if (!kinema_format::readIkObject(r, root, "", scene)) return Result<IkRig>::failure(r.error());
  return std::move(scene.ik);
}

Result<Scene> loadKinemaFile(const std::string& path, const InputLimits& limits) {
  std::string text;
  const std::string error = readTextFile(path, text, limits.maxFileBytes);
  if (!error.empty()) return Result<Scene>::failure(error);
  Json root;
  if (std::string e = parseJsonDocument(text, path, limits, root); !e.empty()) return Result<Scene>::failure(e);
  const size_t inputBytes = text.size();
  std::string().swap(text);  // the tree holds it all now: the text's memory goes before the scene is built
  return readKinemaTree(root, path, limits, inputBytes);
}

std::string saveKinemaFile(const std::string& path, const Scene& scene) {
  std::string bad = scene.skeleton.validate();
  if (bad.empty())
    for (size_t c = 0; c < scene.clips.size() && bad.empty(); ++c) {
      bad = scene.clips[c].validate(scene.skeleton);
      if (!bad.empty()) bad = "clip " + std::to_string(c) + ": " + bad;
    }
  // JSON text is UTF-8 (our readers convert Latin-1 names; a caller may not have).
  for (int i = 0; i < scene.skeleton.size() && bad.empty(); ++i)
    if (!isValidUtf8(scene.skeleton.names[i])) bad = "joint " + std::to_string(i) + " name is not valid UTF-8";
  for (size_t c = 0; c < scene.clips.size() && bad.empty(); ++c)
    if (!isValidUtf8(scene.clips[c].name)) bad = "clip " + std::to_string(c) + " name is not valid UTF-8";
  if (bad.empty() && !scene.ik.empty()) {
    bad = scene.ik.validate(scene.skeleton);
    if (!bad.empty()) bad = "ik: " + bad;
  }
  if (bad.empty() && !scene.simulation.empty()) {
    bad = scene.simulation.validate(scene.skeleton);
    if (!bad.empty()) bad = "simulation: " + bad;
  }
  if (bad.empty() && !scene.pose.local.empty()) {
    bad = scene.pose.validate(scene.skeleton);
    if (!bad.empty()) bad = "pose: " + bad;
  }
  if (bad.empty() && scene.playhead) {
    const int clips = static_cast<int>(scene.clips.size());
    if (!std::isfinite(scene.playhead->time)) bad = "playhead: the time is not finite";
    else if (scene.playhead->clip < 0 || (scene.playhead->clip >= clips && scene.playhead->clip != 0))
      bad = "playhead: clip " + std::to_string(scene.playhead->clip) + " does not exist";
  }
  if (bad.empty()) bad = kinema_format::sceneAssetsError(scene);
  if (!bad.empty()) return oneLineMessage(path + ": not saved: " + bad);
  std::string text;
  try {
    // An image that failed to decode on loading (with a warning) is left out, not refused.
    text = hasUndecodedImages(scene) ? toKinemaJson(withoutUndecodedImages(scene)) : toKinemaJson(scene);
  } catch (const Json::exception& e) {
    return oneLineMessage(path + ": not saved: " + e.what());
  }
  return writeFileAtomically(path, text);
}

}  // namespace kinema
