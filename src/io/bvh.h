#pragma once
#include <string>
#include <vector>

#include "anim/clip.h"
#include "core/result.h"
#include "core/rotation.h"
#include "core/skeleton.h"
#include "io/input_limits.h"
#include "io/up_axis.h"

namespace kinema {

enum class BvhChannel { Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation };
const char* toString(BvhChannel channel);

// A BVH file as written: joints in file order (End Sites included, named after their
// parent with an "_End" suffix), their channel lists, and the raw motion numbers.
struct BvhJoint {
  std::string name;
  int parent = -1;
  glm::vec3 offset{0.0f};
  std::vector<BvhChannel> channels;
  int firstChannel = 0;  // column of channels[0] in each motion line
  bool endSite = false;
  int line = 0;          // where the joint was declared, for messages
};

struct BvhData {
  std::vector<BvhJoint> joints;
  int channelCount = 0;
  int frameCount = 0;
  double frameTime = 0.0;
  std::vector<float> motion;  // frameCount rows of channelCount values

  // Skeleton in file order: rest translation = OFFSET, rest rotation = identity.
  Skeleton skeleton() const;
  // The frame time key times use: frameTime, or 1/kDefaultFrameRate s when frameTime is so small (a
  // denormal) that consecutive frames would get the same float key time.
  double keyFrameTime() const;
  // One clip, key k at time k * keyFrameTime(). Each joint's rotation is the product of its
  // rotation channels in file order (degrees); its translation is the OFFSET with each
  // position channel replacing its component (as Blender does).
  Clip clip() const;
  // The local pose of one frame, computed straight from the motion numbers.
  Pose framePose(int frame) const;
};

// Parses BVH text. `source` names the file in error messages ("walk.bvh:12: ...").
// Accepts CRLF and tabs, any channel order on any joint, several ROOTs, and frame times
// written like ".0083333". Errors are one line naming the file and line.
// `limits` caps the joint count and frames x channels before anything is allocated.
Result<BvhData> parseBvh(const std::string& text, const std::string& source, const InputLimits& limits = {});
Result<BvhData> loadBvh(const std::string& path, const InputLimits& limits = {});

// Turns a Z-up file into Kinema's Y-up one in place: the change of basis C (-90 degrees
// about X: x, y, z -> x, z, -y) applied to every joint, so rest rotations stay identity and
// the motion is exact. OFFSETs become C * offset; a Yposition channel becomes a negated
// Zposition, Zposition becomes Yposition; C Ry(a) C^-1 = Rz(-a) and C Rz(a) C^-1 = Ry(a),
// so rotation channels are relabelled (negated for Y) in their file order.
void convertZUpToYUp(BvhData& data);

}  // namespace kinema
