#include "cli/retarget_command.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "cli/command_line.h"
#include "core/forward_kinematics.h"
#include "core/math.h"
#include "evaluation/scene_poses.h"
#include "io/bone_map_file.h"
#include "io/bvh_writer.h"
#include "io/gltf_writer.h"
#include "io/json_number.h"
#include "io/kinema_file.h"
#include "io/scene_files.h"
#include "retarget/foot_contacts.h"
#include "retarget/foot_locking.h"
#include "retarget/key_reduction.h"
#include "retarget/motion_cleanup.h"
#include "retarget/retarget_clip.h"
#include "retarget/retarget_motion.h"

namespace kinema::cli {

namespace {




// The clip --clip names: an index, or a clip's name.
int chooseClip(const Scene& scene, const std::string& wanted, std::string& error) {
  const int n = static_cast<int>(scene.clips.size());
  if (n == 0) {
    error = scene.source + ": has no clip to retarget (no motion)";
    return -1;
  }
  if (wanted.empty()) return 0;
  for (int i = 0; i < n; ++i)
    if (scene.clips[i].name == wanted) return i;
  char* end = nullptr;
  const long index = std::strtol(wanted.c_str(), &end, 10);
  if (end == wanted.c_str() + wanted.size() && index >= 0 && index < n) return static_cast<int>(index);
  error = scene.source + ": --clip " + wanted + " names no clip (the file has " + std::to_string(n) + " clip" +
          (n == 1 ? "" : "s") + ": give an index 0.." + std::to_string(n - 1) + " or a name)";
  return -1;
}

nlohmann::ordered_json intervalsJson(const std::vector<ContactInterval>& contacts) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (const ContactInterval& c : contacts) a.push_back({c.first, c.last});
  return a;
}

nlohmann::ordered_json unmappedJson(const Skeleton& s, const BoneMap& map, bool sourceSide) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (int j = 0; j < s.size(); ++j)
    if ((sourceSide ? map.targetOf(j) : map.sourceOf(j)) < 0) a.push_back(s.names[j]);
  return a;
}

}  // namespace

CLI::App* addRetargetCommand(CLI::App& app, RetargetOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "retarget", "Put a motion (BVH, glTF or .kinema clip) onto another character's skeleton");
  cmd->add_option("source", o.source, "The file whose clip is played")->required();
  cmd->add_option("target", o.target, "The character that plays it (default: Kinema's default character)");
  cmd->add_option("--out", o.out, "The file to write: .kinema, .gltf, .glb or .bvh (replaced only on success)")->required();
  cmd->add_option("--clip", o.clip, "The source clip, by index or name (default 0)");
  cmd->add_option("--map", o.map, "A bone map file (JSON object: source joint -> target joint; canonical names allowed)");
  cmd->add_flag("--in-place", o.inPlace, "Drop the horizontal root motion");
  cmd->add_flag("--fix-feet", o.fixFeet, "Lock feet in contact with two-bone IK (no foot below the floor)");
  cmd->add_option("--reduce", o.reduce,
                  "POS[,DEG]: thin the keys, keeping every joint within POS file units and every rotation within DEG "
                  "degrees (default 1) at every frame");
  cmd->add_flag("--json", o.json, "Print the report as JSON (map, unmapped joints, foot skate, key counts)");
  addAllowOutsidePathsFlag(cmd, o.allowOutsidePaths);
  addUpOption(cmd, o.up);  // the source's and target's, when BVH
  return cmd;
}

int runRetarget(const RetargetOptions& o) {
  const std::string ext = lowerExtension(o.out);
  if (!canSaveScene(o.out)) {
    std::cerr << "kinema retarget: cannot write '" << ext << "' files (use .kinema, .gltf, .glb or .bvh); see --help\n";
    return kExitUsage;
  }
  double reducePos = 0.0, reduceDeg = 0.0;
  const bool reduce = !o.reduce.empty();
  if (reduce && !parseReduce(o.reduce, reducePos, reduceDeg)) {
    std::cerr << "kinema retarget: --reduce takes POS or POS,DEG (numbers), not '" << o.reduce << "'; see --help\n";
    return kExitUsage;
  }
  if (reduce && (!std::isfinite(reducePos) || !std::isfinite(reduceDeg) || reducePos <= 0.0 || reduceDeg <= 0.0))
    return badInput("--reduce " + o.reduce + ": both tolerances must be positive finite numbers");

  const InputLimits limits = inputLimits(o.allowOutsidePaths);
  Result<Scene> sourceLoaded = loadScene(o.source, limits, upAxisOf(o.up));
  if (!sourceLoaded) return badInput(sourceLoaded.error());
  const Scene& source = sourceLoaded.value();
  std::string error;
  const int clipIndex = chooseClip(source, o.clip, error);
  if (clipIndex < 0) return badInput(error);
  Result<Scene> targetLoaded = loadSceneOrDefault(o.target, limits, upAxisOf(o.up));
  if (!targetLoaded) return badInput(targetLoaded.error());
  Scene target = std::move(targetLoaded.value());
  const std::string targetLabel = o.target.empty() ? std::string("the default character") : o.target;

  const Result<HumanoidReading> sourceHuman = findHumanoid(source.skeleton);
  const Result<HumanoidReading> targetHuman = findHumanoid(target.skeleton);
  BoneMap map;
  std::string mapBy;
  if (o.map.empty()) {
    Result<AutomaticBoneMap> automatic = automaticBoneMap(sourceHuman, targetHuman, o.source, targetLabel);
    if (!automatic) return badInput(automatic.error());
    map = std::move(automatic->map);
    mapBy = automatic->mapBy;
  } else {
    const BoneMapSide from{&source.skeleton, sourceHuman ? &sourceHuman->bones : nullptr, "the source (" + o.source + ")"};
    const BoneMapSide to{&target.skeleton, targetHuman ? &targetHuman->bones : nullptr, "the target (" + targetLabel + ")"};
    Result<BoneMap> loaded = loadBoneMapFile(o.map, from, to, limits);
    if (!loaded) return badInput(loaded.error());
    map = std::move(loaded.value());
    mapBy = "file";
  }
  const bool humans = sourceHuman.ok() && targetHuman.ok();
  RetargetMotionInput input;
  input.source = &source.skeleton;
  input.clip = &source.clips[clipIndex];
  ScenePoses sourcePoses(source, clipIndex);  // the take as it plays: modifiers, keyed IK targets, live chains
  input.sourcePoses = &sourcePoses;
  input.sourceHuman = sourceHuman ? &sourceHuman.value() : nullptr;
  input.target = &target.skeleton;
  input.targetHuman = targetHuman ? &targetHuman.value() : nullptr;
  input.map = &map;
  input.inPlace = o.inPlace;
  input.sourceLabel = o.source;
  input.targetLabel = targetLabel;
  input.mapLabel = o.map;
  Result<RetargetedMotion> retargeted = retargetMotion(input);
  if (!retargeted) return badInput(retargeted.error());
  Clip clip = std::move(retargeted->clip);
  const int frames = clipFrameCount(clip);

  // Foot contacts and skate on the target (needs its legs); the clip keeps both its contacts
  // and the map it came through (.kinema clips[c].foot_contacts, bone_map).
  clip.sourceMap = toClipSourceMap(map, source.skeleton, o.source, clipIndex);
  LegJoints legs[2];
  bool haveLegs = false;
  std::string noLegs;
  if (targetHuman) {
    bool zeroLength = false;
    noLegs = humanoidLegs(target.skeleton, targetHuman->bones, legs, &zeroLength);
    if (zeroLength) return badInput(targetLabel + ": " + noLegs);
    haveLegs = noLegs.empty();
  } else {
    noLegs = targetHuman.error();
  }
  if (o.fixFeet && !haveLegs)
    return badInput(targetLabel + ": --fix-feet needs the target's legs (" + noLegs + ")");
  MotionCleanupReport cleanup;
  if (haveLegs) {
    if (const std::string bad = detectFootContacts(target.skeleton, clip, legs, clip.contacts); !bad.empty())
      return badInput(targetLabel + ": " + bad);
  }
  const FootContacts& contacts = clip.contacts;
  if (haveLegs) {
    MotionCleanupJob job;
    job.skeleton = &target.skeleton;
    job.clip = &clip;
    job.legs[0] = legs[0];
    job.legs[1] = legs[1];
    job.contacts = &clip.contacts;
    job.settings.lockFeet = o.fixFeet;
    job.settings.reduce = reduce;
    job.settings.reduction.positionTolerance = static_cast<float>(reducePos);
    job.settings.reduction.angleTolerance = static_cast<float>(reduceDeg) * kDegree;
    Clip cleaned;
    job.output = &cleaned;
    job.report = &cleanup;
    if (!job.run()) return badInput(o.source + ": " + job.validate());
    clip = std::move(cleaned);
  } else {
    for (const Channel& c : clip.channels) cleanup.keys.keysBefore += c.keyCount();
    cleanup.keys.keysAfter = cleanup.keys.keysBefore;
    if (reduce) {
      Clip reduced;
      KeyReductionJob r;
      r.skeleton = &target.skeleton;
      r.clip = &clip;
      r.settings.positionTolerance = static_cast<float>(reducePos);
      r.settings.angleTolerance = static_cast<float>(reduceDeg) * kDegree;
      r.output = &reduced;
      r.report = &cleanup.keys;
      if (!r.run()) return badInput(o.source + ": " + r.validate());
      clip = std::move(reduced);
    }
  }
  const float skateBefore = cleanup.skateBefore, skateAfter = cleanup.skateAfter;
  const KeyReductionReport& reduction = cleanup.keys;

  // The target's file with its meshes and skins, playing the one new clip.
  Scene out = std::move(target);
  out.clips = {clip};
  out.pose = Pose{};
  out.playhead.reset();
  std::vector<std::string> report;
  error = saveScene(o.out, out, SceneSaveOptions{}, &report);
  for (const std::string& line : report) std::cerr << "kinema retarget: warning: " << line << "\n";
  if (!error.empty()) return badInput(error);

  const Skeleton& ts = out.skeleton;
  if (o.json) {
    nlohmann::ordered_json j;
    j["source"] = o.source;
    j["target"] = o.target.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(o.target);
    j["out"] = o.out;
    j["clip"] = clip.name;
    j["frames"] = frames;
    j["mapBy"] = mapBy;
    j["map"] = boneMapJson(map, source.skeleton, ts);
    nlohmann::ordered_json bones = nlohmann::ordered_json::object();
    if (humans)
      for (int i = 0; i < kHumanoidBoneCount; ++i) {
        const int t = targetHuman->bones.joint[i];
        const int s = sourceHuman->bones.joint[i];
        if (s >= 0 && t >= 0 && map.targetOf(s) == t)
          bones[toString(humanoidBone(i))] = {{"source", source.skeleton.names[s]}, {"target", ts.names[t]}};
      }
    j["humanoidBones"] = bones;
    j["unmapped"] = {{"source", unmappedJson(source.skeleton, map, true)}, {"target", unmappedJson(ts, map, false)}};
    j["rootScale"] = jsonFloat(retargeted->rootScale);
    j["sourceFloor"] = jsonFloat(retargeted->sourceFloor);
    j["targetFloor"] = jsonFloat(retargeted->targetFloor);
    j["contacts"] = {{"left", intervalsJson(contacts.feet[0])}, {"right", intervalsJson(contacts.feet[1])}};
    j["footSkate"] = {{"before", jsonFloat(skateBefore)}, {"after", jsonFloat(skateAfter)}};
    j["keys"] = {{"before", reduction.keysBefore}, {"after", reduction.keysAfter}};
    j["reductionError"] = {{"position", jsonFloat(reduction.maxPositionError)},
                           {"degrees", jsonFloat(reduction.maxAngleError / kDegree)}};
    std::cout << j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
  }
  return kExitOk;
}

}  // namespace kinema::cli
