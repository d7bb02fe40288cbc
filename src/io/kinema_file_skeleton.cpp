// The .kinema file's "skeleton" (required) and "pose" (the editor's working pose, optional)
// sections: each reader beside its writer (docs/kinema-format.md).
#include "io/kinema_file_sections.h"

#include "io/json_number.h"

namespace kinema::kinema_format {

bool readSkeleton(Reader& r, const Json& root, Skeleton& s) {
  const Json* sk = r.member(root, "", "skeleton", true);
  if (!sk) return false;
  if (!sk->is_object()) return r.fail("skeleton", "expected an object");
  const Json* joints = r.member(*sk, "skeleton", "joints", true);
  if (!joints) return false;
  if (!joints->is_array()) return r.fail("skeleton.joints", "expected an array");
  if (joints->size() > static_cast<size_t>(r.limits.maxJoints))
    return r.fail("skeleton.joints",
                  limitExceeded(static_cast<long long>(joints->size()), r.limits.maxJoints, "joints", "maxJoints"));
  for (size_t i = 0; i < joints->size(); ++i) {
    const std::string p = "skeleton.joints[" + std::to_string(i) + "]";
    const Json& j = (*joints)[i];
    if (!j.is_object()) return r.fail(p, "expected an object");
    std::string name;
    long long parent = -1;
    Transform t;
    const Json* v;
    if (!(v = r.member(j, p, "name", true)) || !r.string(*v, p + ".name", name)) return false;
    if (name.empty()) return r.fail(p + ".name", "empty joint name");
    if (!(v = r.member(j, p, "parent", true)) || !r.integer(*v, p + ".parent", parent)) return false;
    if (parent < -1 || parent >= static_cast<long long>(i))
      return r.fail(p + ".parent", "parent " + std::to_string(parent) + " must be -1 or an earlier joint (0.." +
                                       std::to_string(static_cast<long long>(i) - 1) + ")");
    if (!readTransform(r, j, p, t)) return false;
    if (!r.jointIndex.emplace(name, s.size()).second)
      return r.fail(p + ".name", "joint name '" + cutForMessage(name) + "' is used twice");
    s.addJoint(name, static_cast<int>(parent), t);
  }
  return true;
}

Json skeletonToJson(const Skeleton& s) {
  Json joints = Json::array();
  for (int i = 0; i < s.size(); ++i) {
    Json j;
    j["name"] = s.names[i];
    j["parent"] = s.parents[i];
    writeTransform(s.rest[i], j);
    joints.push_back(std::move(j));
  }
  Json skeleton;
  skeleton["joints"] = std::move(joints);
  return skeleton;
}

// ---- the editor's working pose (optional top-level "pose" key) ----
// [{"joint": NAME, "translation": [3], "rotation": [x, y, z, w], "scale": [3]}, ...]; a
// member or a joint left out keeps its rest value.
bool readPose(Reader& r, const Json& root, Scene& scene) {
  const Json* list = r.member(root, "", "pose", false);
  if (!list) return true;
  if (!list->is_array()) return r.fail("pose", "expected an array");
  const Skeleton& s = scene.skeleton;
  Pose pose = Pose::rest(s);
  std::vector<bool> seen(s.size(), false);
  for (size_t i = 0; i < list->size(); ++i) {
    const std::string p = "pose[" + std::to_string(i) + "]";
    const Json& j = (*list)[i];
    if (!j.is_object()) return r.fail(p, "expected an object");
    int joint = -1;
    if (!readJointName(r, j, p, "joint", s, true, joint)) return false;
    if (seen[joint]) return r.fail(p + ".joint", "joint '" + cutForMessage(s.names[joint]) + "' is listed twice");
    seen[joint] = true;
    if (!readTransform(r, j, p, pose.local[joint])) return false;
  }
  scene.pose = std::move(pose);
  return true;
}

Json poseToJson(const Scene& scene) {
  Json list = Json::array();
  for (int i = 0; i < scene.pose.size(); ++i) {
    const Transform& t = scene.pose.local[i];
    Json j;
    j["joint"] = scene.skeleton.names[i];
    writeTransform(t, j);
    list.push_back(std::move(j));
  }
  return list;
}

}  // namespace kinema::kinema_format
