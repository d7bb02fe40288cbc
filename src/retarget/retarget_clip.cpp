#include "retarget/retarget_clip.h"

#include <cmath>

#include "core/forward_kinematics.h"
#include "core/rotation.h"

namespace kinema {

namespace {

// An orthonormal frame from one or two directions (columns: a, then b made perpendicular).
bool frameOf(const glm::vec3& a, const glm::vec3& b, glm::mat3& out) {
  const float la = glm::length(a);
  if (!(la > 0.0f)) return false;
  const glm::vec3 x = a / la;
  glm::vec3 y = b - x * glm::dot(b, x);
  if (!(glm::length(y) > 1e-4f * glm::length(b))) return false;
  y = glm::normalize(y);
  out = glm::mat3(x, y, glm::cross(x, y));
  return true;
}

// The rotation that turns the target's rest bone at pair `p` onto the source's (world).
glm::quat restAlignment(const Skeleton& s, const Skeleton& t, const BoneMap& map, size_t p,
                        const std::vector<glm::vec3>& ps, const std::vector<glm::vec3>& pt) {
  const BonePair& me = map.pairs[p];
  // The nearest mapped pairs below this one (no other mapped pair in between).
  std::vector<const BonePair*> below;
  for (const BonePair& q : map.pairs) {
    if (!(me.source != q.source && s.isInSubtree(q.source, me.source)) || !(me.target != q.target && t.isInSubtree(q.target, me.target))) continue;
    bool direct = true;
    for (const BonePair& r : map.pairs)
      if (&r != &q && (me.source != r.source && s.isInSubtree(r.source, me.source)) && (r.source != q.source && s.isInSubtree(q.source, r.source))) direct = false;
    if (direct) below.push_back(&q);
  }
  if (below.empty()) {
    // An end of the map: the joint's own children (their mean position) on each side.
    glm::vec3 ds(0.0f), dt(0.0f);
    for (int j = 0; j < s.size(); ++j)
      if (s.parents[j] == me.source) ds += ps[j] - ps[me.source];
    for (int j = 0; j < t.size(); ++j)
      if (t.parents[j] == me.target) dt += pt[j] - pt[me.target];
    if (!(glm::length(ds) > 0.0f) || !(glm::length(dt) > 0.0f)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    return fromToRotation(dt, ds);
  }
  const glm::vec3 s0 = ps[below[0]->source] - ps[me.source], t0 = pt[below[0]->target] - pt[me.target];
  if (below.size() >= 2) {
    const glm::vec3 s1 = ps[below[1]->source] - ps[me.source], t1 = pt[below[1]->target] - pt[me.target];
    glm::mat3 fs, ft;
    if (frameOf(s0, s1, fs) && frameOf(t0, t1, ft)) return safeNormalize(glm::quat_cast(fs * glm::transpose(ft)));
  }
  if (!(glm::length(s0) > 0.0f) || !(glm::length(t0) > 0.0f)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  return fromToRotation(t0, s0);
}

}  // namespace

int clipFrameCount(const Clip& clip) {
  const long long last = ownFrameGrid(clip).nearestFrame(clip.duration());
  return static_cast<int>(std::max(0LL, last)) + 1;
}

Result<float> restHipHeight(const Skeleton& skeleton, const HumanoidMap& humanoid) {
  const int hips = humanoid[HumanoidBone::Hips];
  if (hips < 0) return Result<float>::failure("no hips to measure the legs from");
  const std::vector<glm::mat4> world = computeWorld(skeleton, Pose::rest(skeleton));
  bool any = false;
  float lowest = 0.0f;
  for (HumanoidBone b : {HumanoidBone::LeftFoot, HumanoidBone::RightFoot, HumanoidBone::LeftToes, HumanoidBone::RightToes}) {
    const int j = humanoid[b];
    if (j < 0) continue;
    lowest = any ? std::min(lowest, world[j][3].y) : world[j][3].y;
    any = true;
  }
  if (!any) return Result<float>::failure("no feet to measure the legs to");
  const float h = world[hips][3].y - lowest;
  if (!(h > 0.0f) || !std::isfinite(h))
    return Result<float>::failure("zero-length legs: the hips ('" + skeleton.names[hips] +
                                  "') are not above the feet in the rest pose");
  return h;
}

namespace {

constexpr HumanoidBone kFeet[] = {HumanoidBone::LeftFoot, HumanoidBone::RightFoot, HumanoidBone::LeftToes,
                                  HumanoidBone::RightToes};

// The lowest world Y of the humanoid's foot and toe joints in one set of world matrices.
bool lowestFoot(const std::vector<glm::mat4>& world, const HumanoidMap& humanoid, float& lowest) {
  bool any = false;
  for (HumanoidBone b : kFeet) {
    const int j = humanoid[b];
    if (j < 0) continue;
    lowest = any ? std::min(lowest, world[j][3].y) : world[j][3].y;
    any = true;
  }
  return any;
}

}  // namespace

Result<FootFloors> footFloors(const Skeleton& source, const Clip& clip, const HumanoidMap& sourceHumanoid,
                              const Skeleton& target, const HumanoidMap& targetHumanoid, PoseSource* sourcePoses) {
  FootFloors floors;
  if (!lowestFoot(computeWorld(target, Pose::rest(target)), targetHumanoid, floors.target))
    return Result<FootFloors>::failure("no feet to stand the target on");
  bool any = false;
  ClipPoses bare(source, clip);
  PoseSource& poses = sourcePoses ? *sourcePoses : bare;
  Pose pose = Pose::rest(source);
  std::vector<glm::mat4> world;
  for (int f = 0, n = clipFrameCount(clip); f < n; ++f) {
    poses.poseAt(ownFrameGrid(clip).frameToTime(f), pose);
    computeWorld(source, pose, world);
    float low = 0.0f;
    if (!lowestFoot(world, sourceHumanoid, low)) return Result<FootFloors>::failure("no feet to find the take's floor from");
    floors.source = any ? std::min(floors.source, low) : low;
    any = true;
  }
  if (!std::isfinite(floors.source) || !std::isfinite(floors.target))
    return Result<FootFloors>::failure("the feet's heights are not finite");
  return floors;
}

std::string RetargetJob::validate() const {
  if (!source || !target || !sourceClip || !map || !output) return "retarget: missing input or output";
  if (!hasOwnFrameRate(*sourceClip)) return "retarget: the source clip has no frame rate of its own";
  if (source->empty() || target->empty()) return "retarget: empty skeleton";
  const std::string m = map->validate(*source, *target);
  if (!m.empty()) return m;
  if (map->pairs.empty()) return "retarget: the bone map pairs no joints";
  const std::string c = sourceClip->validate(*source);
  if (!c.empty()) return "retarget: source clip: " + c;
  if ((sourceRoot < 0) != (targetRoot < 0)) return "retarget: root motion needs both root joints";
  if (sourceRoot >= source->size() || targetRoot >= target->size()) return "retarget: root joint out of range";
  if (targetRoot >= 0 && map->sourceOf(targetRoot) < 0) return "retarget: the target root is not mapped";
  if (!(rootScale > 0.0f) || !std::isfinite(rootScale)) return "retarget: root scale must be positive and finite";
  if (!std::isfinite(sourceFloor) || !std::isfinite(targetFloor)) return "retarget: the floors must be finite";
  for (int foot : targetFeet)
    if (foot < 0 || foot >= target->size()) return "retarget: a foot joint is out of range";
  if (!targetFeet.empty() && targetRoot < 0) return "retarget: grounding the feet needs root motion";
  return {};
}

bool RetargetJob::run() const {
  if (!validate().empty()) return false;
  const Skeleton& s = *source;
  const Skeleton& t = *target;
  const BoneMap& m = *map;
  const std::vector<glm::mat4> restS = computeWorld(s, Pose::rest(s));
  const std::vector<glm::mat4> restT = computeWorld(t, Pose::rest(t));
  std::vector<glm::vec3> ps, pt;
  for (const glm::mat4& w : restS) ps.push_back(glm::vec3(w[3]));
  for (const glm::mat4& w : restT) pt.push_back(glm::vec3(w[3]));
  std::vector<int> pairOfTarget(t.size(), -1);
  std::vector<glm::quat> inverseRestS(m.pairs.size()), alignedRestT(m.pairs.size());
  for (size_t p = 0; p < m.pairs.size(); ++p) {
    pairOfTarget[m.pairs[p].target] = static_cast<int>(p);
    inverseRestS[p] = glm::conjugate(rotationOf(restS[m.pairs[p].source]));
    alignedRestT[p] = safeNormalize(restAlignment(s, t, m, p, ps, pt) * rotationOf(restT[m.pairs[p].target]));
  }

  const int frames = clipFrameCount(*sourceClip);
  Clip out;
  out.name = sourceClip->name;
  out.frameTime = ownFrameGrid(*sourceClip).secondsPerFrame;
  std::vector<int> channelOf(t.size(), -1);
  for (int j = 0; j < t.size(); ++j) {
    if (pairOfTarget[j] < 0) continue;
    channelOf[j] = static_cast<int>(out.channels.size());
    out.channels.emplace_back(j, ChannelTarget::Rotation, Interpolation::Linear, std::vector<float>{},
                              std::vector<glm::vec4>{});
  }
  int rootChannel = -1;
  if (targetRoot >= 0) {
    rootChannel = static_cast<int>(out.channels.size());
    out.channels.emplace_back(targetRoot, ChannelTarget::Translation, Interpolation::Linear, std::vector<float>{},
                              std::vector<glm::vec4>{});
  }
  for (Channel& c : out.channels) {
    c.times.reserve(frames);
    c.values.reserve(frames);
  }

  // Grounding: the lowest the target's feet come over the take, and per frame the root's
  // parent's world rotation (a world shift of the root is a local shift through it).
  float lowestFoot = 0.0f;
  bool anyFoot = false;
  std::vector<glm::mat3> rootParentRotation;
  if (targetRoot >= 0) rootParentRotation.reserve(frames);
  ClipPoses bare(s, *sourceClip);
  PoseSource& poses = sourcePoses ? *sourcePoses : bare;
  Pose sourcePose = Pose::rest(s);
  std::vector<glm::mat4> worldS;
  std::vector<glm::quat> rotT(t.size());
  std::vector<glm::mat4> worldT(t.size());
  for (int f = 0; f < frames; ++f) {
    const float time = ownFrameGrid(*sourceClip).frameToTime(f);
    poses.poseAt(time, sourcePose);
    computeWorld(s, sourcePose, worldS);
    Pose targetPose = Pose::rest(t);
    for (int j = 0; j < t.size(); ++j) {
      const int parent = t.parents[j];
      const glm::quat parentRot = parent >= 0 ? rotT[parent] : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
      Transform& local = targetPose.local[j];
      const int p = pairOfTarget[j];
      if (p >= 0) {
        const glm::quat turn = rotationOf(worldS[m.pairs[p].source]) * inverseRestS[p];
        const glm::quat world = safeNormalize(turn * alignedRestT[p]);
        local.rotation = safeNormalize(glm::conjugate(parentRot) * world);
      }
      if (j == targetRoot) {
        // Horizontally scaled about the world origin; the height from each side's floor.
        glm::vec3 world = rootScale * glm::vec3(worldS[sourceRoot][3]);
        world.y = targetFloor + rootScale * (worldS[sourceRoot][3].y - sourceFloor);
        if (inPlace) world.x = pt[j].x, world.z = pt[j].z;
        const glm::mat4 parentWorld = parent >= 0 ? worldT[parent] : glm::mat4(1.0f);
        local.translation = glm::vec3(glm::inverse(parentWorld) * glm::vec4(world, 1.0f));
        rootParentRotation.push_back(glm::mat3(parentWorld));
      }
      rotT[j] = safeNormalize(parentRot * local.rotation);
      worldT[j] = (parent >= 0 ? worldT[parent] : glm::mat4(1.0f)) * local.toMatrix();
      if (channelOf[j] >= 0) {
        Channel& c = out.channels[channelOf[j]];
        c.times.push_back(time);
        const glm::quat q = f > 0 ? sameHemisphere(local.rotation, glm::quat(c.values.back().w, c.values.back().x,
                                                                              c.values.back().y, c.values.back().z))
                                  : local.rotation;
        c.values.push_back(glm::vec4(q.x, q.y, q.z, q.w));
      }
      if (j == targetRoot) {
        Channel& c = out.channels[rootChannel];
        c.times.push_back(time);
        c.values.push_back(glm::vec4(local.translation, 0.0f));
      }
    }
    for (int foot : targetFeet) {
      lowestFoot = anyFoot ? std::min(lowestFoot, worldT[foot][3].y) : worldT[foot][3].y;
      anyFoot = true;
    }
  }
  // The whole take moved up or down so its lowest foot stands on the target's floor: the
  // hip-height ratio alone leaves it off by the legs' differing proportions.
  if (rootChannel >= 0 && anyFoot && std::isfinite(lowestFoot)) {
    const glm::vec3 up(0.0f, targetFloor - lowestFoot, 0.0f);
    Channel& c = out.channels[rootChannel];
    for (size_t f = 0; f < c.values.size(); ++f)
      c.values[f] += glm::vec4(glm::inverse(rootParentRotation[f]) * up, 0.0f);
  }
  *output = std::move(out);
  return true;
}

}  // namespace kinema
