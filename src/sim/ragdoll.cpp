#include "sim/ragdoll.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "anim/sampling.h"
#include "core/forward_kinematics.h"
#include "core/rotation.h"

namespace kinema {
namespace {

btVector3 bt(const glm::vec3& v) { return btVector3(v.x, v.y, v.z); }
glm::vec3 fromBt(const btVector3& v) { return glm::vec3(v.x(), v.y(), v.z()); }

// A rigid transform (rotation + translation) as a matrix, and to / from Bullet's.
glm::mat4 rigid(const glm::quat& q, const glm::vec3& t) {
  glm::mat4 m = glm::mat4_cast(q);
  m[3] = glm::vec4(t, 1.0f);
  return m;
}
btTransform toBt(const glm::mat4& m) {
  const glm::quat q = glm::normalize(glm::quat_cast(glm::mat3(m)));
  return btTransform(btQuaternion(q.x, q.y, q.z, q.w), bt(glm::vec3(m[3])));
}
glm::mat4 fromBt(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  return rigid(glm::quat(q.w(), q.x(), q.y(), q.z()), fromBt(t.getOrigin()));
}
glm::mat4 rigidInverse(const glm::mat4& m) {
  const glm::mat3 rt = glm::transpose(glm::mat3(m));
  glm::mat4 out(rt);
  out[3] = glm::vec4(-(rt * glm::vec3(m[3])), 1.0f);
  return out;
}

// The rotation of an affine matrix whose columns may carry a scale.
// Each joint's rigid frame in the world (scale dropped).
std::vector<glm::mat4> rigidFrames(const Skeleton& s, const Pose& pose) {
  std::vector<glm::mat4> world = computeWorld(s, pose);
  for (glm::mat4& m : world) m = rigid(rotationOf(m), glm::vec3(m[3]));
  return world;
}

RotateOrder bulletOrder(EulerOrder o) {
  switch (o) {
    case EulerOrder::XYZ: return RO_XYZ;
    case EulerOrder::XZY: return RO_XZY;
    case EulerOrder::YXZ: return RO_YXZ;
    case EulerOrder::YZX: return RO_YZX;
    case EulerOrder::ZXY: return RO_ZXY;
    case EulerOrder::ZYX: return RO_ZYX;
  }
  return RO_XYZ;
}

}  // namespace

// Bullet's objects, torn down in the order Bullet needs (constraints, bodies, then the world).
struct Ragdoll::World {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::unique_ptr<btCollisionShape> groundShape;
  std::unique_ptr<btRigidBody> ground;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  std::vector<std::unique_ptr<btTypedConstraint>> constraints;
  ~World() {
    for (auto& c : constraints) world.removeConstraint(c.get());
    for (auto& b : bodies) world.removeRigidBody(b.get());
    if (ground) world.removeRigidBody(ground.get());
  }
};

Ragdoll::~Ragdoll() = default;

Result<std::unique_ptr<Ragdoll>> Ragdoll::create(const Skeleton& s, const RagdollSettings& settings,
                                                 const std::vector<RagdollBody>& bodies,
                                                 const std::vector<JointLimit>& limits, const Pose& pose,
                                                 const Pose* previousPose, float interval) {
  using R = Result<std::unique_ptr<Ragdoll>>;
  if (std::string e = settings.validate(s); !e.empty()) return R::failure(e);
  if (std::string e = pose.validate(s); !e.empty()) return R::failure("ragdoll '" + settings.name + "': " + e);
  if (previousPose && !previousPose->validate(s).empty()) return R::failure("ragdoll '" + settings.name + "': bad previous pose");
  if (bodies.empty()) return R::failure("ragdoll '" + settings.name + "': no bones to simulate (the root has no children)");
  if (limits.size() != static_cast<size_t>(s.size())) return R::failure("ragdoll: one limit per joint is needed");
  if (!(interval > 0.0f) || !std::isfinite(interval)) return R::failure("ragdoll: the pose interval must be above 0");
  for (size_t b = 0; b < bodies.size(); ++b) {
    const RagdollBody& body = bodies[b];
    if (body.joint < 0 || body.joint >= s.size() || body.parentBody >= static_cast<int>(b) ||
        (body.parentBody >= 0 && bodies[body.parentBody].joint != s.parents[body.joint]) ||
        !(body.radius > 0.0f) || !(body.mass > 0.0f) || !isFinite(body.tail))
      return R::failure("ragdoll '" + settings.name + "': body " + std::to_string(b) + " is malformed");
    if (body.parentBody >= 0 && !limits[body.joint].validate().empty())
      return R::failure("ragdoll '" + settings.name + "': joint '" + s.names[body.joint] + "': " + limits[body.joint].validate());
  }

  std::unique_ptr<Ragdoll> r(new Ragdoll);
  r->skeleton_ = &s;
  r->bodies_ = bodies;
  r->limits_ = limits;
  r->world_ = std::make_unique<World>();
  World& w = *r->world_;
  w.world.setGravity(bt(settings.gravity));
  // More solver rounds than Bullet's default 10: a long chain of limits holds within a degree.
  w.world.getSolverInfo().m_numIterations = 150;

  constexpr int kGroundGroup = btBroadphaseProxy::StaticFilter, kBodyGroup = btBroadphaseProxy::CharacterFilter;
  w.groundShape = std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), settings.groundHeight);
  w.ground = std::make_unique<btRigidBody>(0.0f, nullptr, w.groundShape.get());
  w.ground->setFriction(settings.friction);
  w.ground->setRestitution(settings.restitution);
  w.world.addRigidBody(w.ground.get(), kGroundGroup, kBodyGroup);

  std::vector<glm::mat4> frames = rigidFrames(s, pose);
  // A body that starts in the ground would be thrown out of it: the whole ragdoll is lifted
  // until its lowest capsule touches the ground (a standing character's feet do).
  float lowest = std::numeric_limits<float>::infinity();
  for (const RagdollBody& body : bodies) {
    const glm::vec3 head(frames[body.joint][3]);
    const glm::vec3 tail = head + glm::mat3(frames[body.joint]) * body.tail;
    lowest = std::min(lowest, std::min(head.y, tail.y) - body.radius);
  }
  const float lift = settings.groundHeight - lowest;
  if (lift > 0.0f)
    for (glm::mat4& m : frames) m[3].y += lift;
  std::vector<glm::mat4> before = frames;
  if (previousPose) {
    before = rigidFrames(s, *previousPose);
    if (lift > 0.0f)
      for (glm::mat4& m : before) m[3].y += lift;
  }
  std::vector<glm::mat4> bodyWorld(bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    const RagdollBody& body = bodies[b];
    const float length = glm::length(body.tail);
    // The capsule's frame in the joint's: centred on the bone, its Y axis along it.
    const glm::mat4 offset =
        length > 0.0f ? rigid(fromToRotation({0, 1, 0}, body.tail / length), 0.5f * body.tail) : glm::mat4(1.0f);
    r->bodyFromJoint_.push_back(rigidInverse(offset));
    if (length > 0.0f) w.shapes.push_back(std::make_unique<btCapsuleShape>(body.radius, length));
    else w.shapes.push_back(std::make_unique<btSphereShape>(body.radius));
    btVector3 inertia(0, 0, 0);
    w.shapes.back()->calculateLocalInertia(body.mass, inertia);
    bodyWorld[b] = frames[body.joint] * offset;
    btRigidBody::btRigidBodyConstructionInfo info(body.mass, nullptr, w.shapes.back().get(), inertia);
    info.m_startWorldTransform = toBt(bodyWorld[b]);
    info.m_friction = settings.friction;
    info.m_restitution = settings.restitution;
    info.m_linearDamping = settings.damping;
    info.m_angularDamping = settings.damping;
    auto rb = std::make_unique<btRigidBody>(info);
    // The motion it had: finite differences of the animated pose.
    const glm::mat4 was = before[body.joint] * offset;
    rb->setLinearVelocity(bt((glm::vec3(bodyWorld[b][3]) - glm::vec3(was[3])) / interval));
    const glm::quat turn = rotationOf(bodyWorld[b]) * glm::inverse(rotationOf(was));
    const glm::quat shortest = turn.w < 0.0f ? -turn : turn;
    const float angle = 2.0f * std::atan2(glm::length(glm::vec3(shortest.x, shortest.y, shortest.z)), shortest.w);
    const glm::vec3 axis = angle > 0.0f ? glm::normalize(glm::vec3(shortest.x, shortest.y, shortest.z)) : glm::vec3(0.0f);
    rb->setAngularVelocity(bt(axis * (angle / interval)));
    w.world.addRigidBody(rb.get(), kBodyGroup, kGroundGroup);
    w.bodies.push_back(std::move(rb));
  }

  // The joints: one frame on the parent body is the joint's rest frame under the parent, the
  // other on the child body the joint's frame, each turned by Q (X onto the limit's axis),
  // so the rotation between them is Q^-1 d Q for d = rest^-1 * local, the rotation the
  // limit constrains.
  for (size_t b = 0; b < bodies.size(); ++b) {
    const RagdollBody& body = bodies[b];
    if (body.parentBody < 0) continue;
    const int j = body.joint;
    const glm::mat4& parentFrame = frames[s.parents[j]];
    const glm::vec3 head(frames[j][3]);
    const glm::quat restWorld = rotationOf(parentFrame) * s.rest[j].rotation;
    const glm::quat jointWorld = rotationOf(frames[j]);
    const JointLimit& limit = limits[j];
    btRigidBody& a = *w.bodies[body.parentBody];
    btRigidBody& c = *w.bodies[b];
    const glm::mat4 aInv = rigidInverse(bodyWorld[body.parentBody]), cInv = rigidInverse(bodyWorld[b]);
    std::unique_ptr<btTypedConstraint> constraint;
    if (limit.type == JointLimitType::Hinge || limit.type == JointLimitType::Euler || limit.type == JointLimitType::Cone) {
      const bool hinge = limit.type == JointLimitType::Hinge, cone = limit.type == JointLimitType::Cone;
      const glm::quat q = hinge || cone ? fromToRotation({1, 0, 0}, limit.axis) : glm::quat(1, 0, 0, 0);
      // The child goes first: Bullet reads its angles off the transpose of A^-1 B (its
      // matrixToEuler* index the matrix column-major), i.e. off B^-1 A = Q^-1 d Q this way round.
      auto six = std::make_unique<btGeneric6DofSpring2Constraint>(
          c, a, toBt(cInv * rigid(jointWorld * q, head)), toBt(aInv * rigid(restWorld * q, head)),
          hinge ? RO_XYZ : cone ? RO_YZX : bulletOrder(limit.order));
      six->setLinearLowerLimit(btVector3(0, 0, 0));
      six->setLinearUpperLimit(btVector3(0, 0, 0));
      if (hinge) {
        six->setAngularLowerLimit(btVector3(limit.minAngle, 0, 0));
        six->setAngularUpperLimit(btVector3(limit.maxAngle, 0, 0));
      } else if (cone) {
        // A cone as swing Ry(b) Rz(c) then twist Rx(t) about the bone (Bullet's cone-twist
        // joint let a spine swing 25 degrees past its cone): |b|, |c| <= cone / sqrt 2 keep the
        // swing inside the cone, and the twist range narrows by the most twist such a swing
        // carries, 2 atan(tan^2(cone / (2 sqrt 2))), so the swing-twist reading stays inside.
        const float s = limit.coneAngle / std::sqrt(2.0f);
        const float t = std::tan(0.5f * s);
        const float carried = 2.0f * std::atan(t * t);
        float lo = limit.twistMin + carried, hi = limit.twistMax - carried;
        if (lo > hi) lo = hi = 0.5f * (limit.twistMin + limit.twistMax);
        six->setAngularLowerLimit(btVector3(lo, -s, -s));
        six->setAngularUpperLimit(btVector3(hi, s, s));
      } else {
        six->setAngularLowerLimit(bt(limit.eulerMin));
        six->setAngularUpperLimit(bt(limit.eulerMax));
      }
      // Limit stops corrected hard (Bullet's default lets a landing on straight knees push
      // them 12 degrees past), with no give.
      for (int axis = 0; axis < 6; ++axis) {
        six->setParam(BT_CONSTRAINT_STOP_ERP, 0.9f, axis);
        six->setParam(BT_CONSTRAINT_STOP_CFM, 0.0f, axis);
      }
      constraint = std::move(six);
    } else {  // no limit: a ball joint
      constraint = std::make_unique<btPoint2PointConstraint>(a, c, bt(glm::vec3(aInv * glm::vec4(head, 1.0f))),
                                                             bt(glm::vec3(cInv * glm::vec4(head, 1.0f))));
    }
    w.world.addConstraint(constraint.get(), true);  // true: the two bodies never collide
    w.constraints.push_back(std::move(constraint));
  }
  return R(std::move(r));
}

void Ragdoll::step(float dt) {
  if (!(dt > 0.0f) || !std::isfinite(dt)) return;
  const int n = std::max(1, static_cast<int>(std::ceil(dt * kRagdollStepsPerSecond - 1e-4f)));
  // Fixed equal steps, never Bullet's own accumulator: the same frames give the same bits.
  for (int i = 0; i < n; ++i) world_->world.stepSimulation(dt / static_cast<float>(n), 0);
  steps_ += n;
}

void Ragdoll::writePose(Pose& pose) const {
  const Skeleton& s = *skeleton_;
  std::vector<glm::mat4> frame(static_cast<size_t>(s.size()));
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const int j = bodies_[b].joint;
    frame[j] = fromBt(world_->bodies[b]->getWorldTransform()) * bodyFromJoint_[b];
    const glm::quat q = rotationOf(frame[j]);
    if (bodies_[b].parentBody < 0) {
      const int p = s.parents[j];
      glm::mat4 parentWorld(1.0f);
      if (p >= 0) {
        // The root's parent as the animation has it now (it is not simulated).
        const std::vector<glm::mat4> world = computeWorld(s, pose);
        parentWorld = world[p];
      }
      pose.local[j].rotation = glm::normalize(glm::inverse(rotationOf(parentWorld)) * q);
      pose.local[j].translation = glm::vec3(glm::inverse(parentWorld) * frame[j][3]);
    } else {
      pose.local[j].rotation = glm::normalize(glm::inverse(rotationOf(frame[s.parents[j]])) * q);
    }
  }
}

float Ragdoll::largestLimitExcess(const Pose& pose, int* joint) const {
  float worst = 0.0f;
  if (joint) *joint = -1;
  for (const RagdollBody& b : bodies_) {
    if (b.parentBody < 0 || !limits_[b.joint].active()) continue;
    const float excess = jointLimitViolation(limits_[b.joint], skeleton_->rest[b.joint].rotation, pose.local[b.joint].rotation);
    if (excess > worst) {
      worst = excess;
      if (joint) *joint = b.joint;
    }
  }
  return worst;
}

float Ragdoll::largestSpeed() const {
  float fastest = 0.0f;
  for (const auto& b : world_->bodies) fastest = std::max(fastest, static_cast<float>(b->getLinearVelocity().length()));
  return fastest;
}

Result<Clip> bakeRagdoll(const Skeleton& skeleton, const Clip& clip, const RagdollSettings& settings,
                         const std::vector<RagdollBody>& bodies, const std::vector<JointLimit>& limits,
                         long long firstFrame, long long lastFrame, RagdollBakeReport* report,
                         const std::function<void(long long frame)>& frameDone, PoseSource* poses) {
  if (lastFrame < firstFrame) return Result<Clip>::failure("the last frame is before the first");
  if (lastFrame - firstFrame > 1000000) return Result<Clip>::failure("more than 1,000,000 frames to bake");
  if (std::string e = settings.validate(skeleton); !e.empty()) return Result<Clip>::failure(e);
  if (!hasOwnFrameRate(clip)) return Result<Clip>::failure("the clip has no frame rate of its own (frame_time)");
  RagdollBakeReport rep;
  rep.bodies = static_cast<int>(bodies.size());
  const long long start = std::max(firstFrame, settings.startFrame);
  const float dt = static_cast<float>(ownFrameGrid(clip).secondsPerFrame);
  std::vector<Channel> rotations(bodies.size()), translation(1);
  for (size_t b = 0; b < bodies.size(); ++b)
    rotations[b] = Channel(bodies[b].joint, ChannelTarget::Rotation, Interpolation::Linear, {}, {});
  const int rootJoint = bodies.empty() ? -1 : bodies[0].joint;
  translation[0] = Channel(rootJoint, ChannelTarget::Translation, Interpolation::Linear, {}, {});
  std::unique_ptr<Ragdoll> ragdoll;
  ClipPoses bare(skeleton, clip);
  PoseSource& source = poses ? *poses : bare;
  Pose pose = Pose::rest(skeleton);
  for (long long f = firstFrame; f <= lastFrame; ++f) {
    const float t = ownFrameGrid(clip).frameToTime(f);
    source.poseAt(t, pose);
    if (f == start) {
      // The frame before, for the bodies' starting velocities.
      Pose previous = Pose::rest(skeleton);
      source.poseAt(ownFrameGrid(clip).frameToTime(f - 1), previous);
      Result<std::unique_ptr<Ragdoll>> made = Ragdoll::create(skeleton, settings, bodies, limits, pose, &previous, dt);
      if (!made) return Result<Clip>::failure(made.error());
      ragdoll = std::move(made.value());
      rep.firstFrame = f;
    } else if (ragdoll) {
      ragdoll->step(dt);
    }
    if (ragdoll) {
      ragdoll->writePose(pose);
      int joint = -1;
      const float excess = ragdoll->largestLimitExcess(pose, &joint);
      if (excess > rep.largestLimitExcess) rep.largestLimitExcess = excess, rep.worstJoint = joint;
      rep.lastFrame = f;
    }
    for (size_t b = 0; b < bodies.size(); ++b) {
      const glm::quat q = pose.local[bodies[b].joint].rotation;
      rotations[b].times.push_back(t);
      rotations[b].values.emplace_back(q.x, q.y, q.z, q.w);
    }
    if (rootJoint >= 0) {
      translation[0].times.push_back(t);
      translation[0].values.emplace_back(pose.local[rootJoint].translation, 0.0f);
    }
    if (frameDone) frameDone(f);
  }
  if (ragdoll) rep.steps = ragdoll->stepsTaken();
  if (report) *report = rep;
  Clip out = clip;
  if (out.frameTime <= 0.0) out.frameTime = ownFrameGrid(clip).secondsPerFrame;
  auto baked = [&](const Channel& c) {
    if (c.joint == rootJoint && c.target == ChannelTarget::Translation) return true;
    if (c.target != ChannelTarget::Rotation && c.target != ChannelTarget::Euler) return false;
    return std::any_of(bodies.begin(), bodies.end(), [&](const RagdollBody& b) { return b.joint == c.joint; });
  };
  out.channels.erase(std::remove_if(out.channels.begin(), out.channels.end(), baked), out.channels.end());
  for (Channel& c : rotations) out.channels.push_back(std::move(c));
  if (rootJoint >= 0) out.channels.push_back(std::move(translation[0]));
  return out;
}

}  // namespace kinema
