#include "editor/state_dump.h"

#include <nlohmann/json.hpp>

namespace kinema {

namespace {
using json = nlohmann::json;
json vec(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }
json jointName(const EditorState& s, int j) {
  return j >= 0 && j < s.scene.skeleton.size() ? json(s.scene.skeleton.names[j]) : json(nullptr);
}
}  // namespace

std::string editorStateJson(const EditorState& s, int windowWidth, int windowHeight, long long frames) {
  json out;
  out["path"] = s.path;
  out["dirty"] = s.dirty;
  out["undo_depth"] = s.undoDepth;
  out["frames"] = frames;
  out["window"] = {{"width", windowWidth}, {"height", windowHeight}};
  out["tool"] = modalToolName(s.tool.mode);
  json selection = json::array();
  for (int j : s.selection) selection.push_back(jointName(s, j));
  out["selection"] = selection;
  out["active"] = jointName(s, s.activeJoint);
  out["hovered"] = jointName(s, s.hoveredJoint);
  out["auto_ik"] = s.view.autoIk;
  const OrbitCamera& c = s.camera;
  out["camera"] = {{"azimuth", c.azimuthDeg},   {"elevation", c.elevationDeg}, {"distance", c.distance},
                   {"target", vec(c.target)},   {"fov_y", c.fovYDeg},          {"orthographic", s.orthographic},
                   {"eye", vec(c.eye())}};
  json joints = json::array();
  for (int j = 0; j < s.scene.skeleton.size(); ++j) {
    json e;
    e["name"] = s.scene.skeleton.names[j];
    e["parent"] = s.scene.skeleton.parents[j];
    if (j < s.pose.size()) {
      const glm::quat& q = s.pose.local[j].rotation;
      e["rotation"] = json::array({q.x, q.y, q.z, q.w});
      e["translation"] = vec(s.pose.local[j].translation);
    }
    if (j < static_cast<int>(s.world.size())) e["world_position"] = vec(glm::vec3(s.world[j][3]));
    joints.push_back(e);
  }
  out["joints"] = joints;
  json targets = json::array();
  for (size_t i = 0; i < s.scene.ik.targets.size(); ++i) {
    const IkTarget& t = s.scene.ik.targets[i];
    json e = {{"effector", jointName(s, t.effector)}, {"root", jointName(s, t.root)}, {"position", vec(t.position)}};
    if (i < s.ikStatus.size()) {
      e["iterations"] = s.ikStatus[i].iterations;
      e["error"] = s.ikStatus[i].error;
      e["milliseconds"] = s.ikStatus[i].milliseconds;
      e["converged"] = s.ikStatus[i].converged;
    }
    targets.push_back(e);
  }
  out["ik_targets"] = targets;
  return out.dump(1) + "\n";
}

}  // namespace kinema
