#include "retarget/bone_map.h"

#include <algorithm>
#include <cctype>

#include "core/forward_kinematics.h"

namespace kinema {

namespace {

enum Side { kLeft = 0, kRight = 1, kNoSide = 2 };
enum Limb { kShoulder, kUpperArm, kLowerArm, kHand, kUpperLeg, kLowerLeg, kFoot, kToes };

HumanoidBone limbBone(int side, Limb limb) {
  const int arms = index(HumanoidBone::LeftShoulder), legs = index(HumanoidBone::LeftUpperLeg);
  if (limb <= kHand) return humanoidBone(arms + side * 4 + limb);
  return humanoidBone(legs + side * 4 + (limb - kUpperLeg));
}
HumanoidBone fingerBone(int side, int finger, int segment) {
  return humanoidBone(index(kFirstFingerBone) + side * 15 + finger * 3 + segment);
}

// A name cut into lower-case words: at separators, at lower->upper and letter<->digit
// changes, and before the last capital of a run of capitals ("LHipJoint" -> l hip joint).
// Anything up to the last ':' or '|' (Mixamo's "mixamorig:") is dropped first.
std::vector<std::string> words(const std::string& full) {
  const size_t cut = full.find_last_of(":|");
  const std::string name = cut == std::string::npos ? full : full.substr(cut + 1);
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) out.push_back(cur);
    cur.clear();
  };
  auto up = [](char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; };
  auto low = [](char c) { return std::islower(static_cast<unsigned char>(c)) != 0; };
  auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      flush();
      continue;
    }
    if (!cur.empty()) {
      const char p = name[i - 1];
      const bool split = (low(p) && up(c)) || (digit(p) != digit(c)) ||
                         (up(p) && up(c) && i + 1 < name.size() && low(name[i + 1]));
      if (split) flush();
    }
    cur += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  flush();
  return out;
}

struct NameParts {
  int side = kNoSide;
  std::string key;  // the words that are neither side, number nor rig prefix, joined
  int number = -1;  // the first number in the name
};

NameParts parseName(const std::string& name) {
  std::vector<std::string> w = words(name);
  static const char* const kPrefixes[] = {"def", "org", "mch", "b", "bip", "jnt", "skeleton", "mixamorig"};
  if (w.size() > 1 && std::find(std::begin(kPrefixes), std::end(kPrefixes), w.front()) != std::end(kPrefixes))
    w.erase(w.begin());
  NameParts p;
  bool left = false, right = false;
  for (const std::string& s : w) {
    if (s == "l" || s == "left") left = true;
    else if (s == "r" || s == "right") right = true;
    else if (std::isdigit(static_cast<unsigned char>(s[0]))) {
      if (p.number < 0) p.number = std::atoi(s.c_str());
    } else {
      p.key += s;
    }
  }
  if (left != right) p.side = left ? kLeft : kRight;
  return p;
}

bool oneOf(const std::string& key, std::initializer_list<const char*> options) {
  for (const char* o : options)
    if (key == o) return true;
  return false;
}

struct Claim {
  int score = 0;
  int joint = -1;
  HumanoidBone bone = HumanoidBone::Hips;
};

// The canonical bones a joint's name may mean, with how sure the name is (higher wins).
// The spine chain is left to the hierarchy: "Spine" is the first spine joint in one
// convention and the second in another.
void claimsOf(const std::string& name, int joint, std::vector<Claim>& out) {
  const NameParts p = parseName(name);
  auto add = [&](HumanoidBone b, int score) { out.push_back({score, joint, b}); };
  const std::string& k = p.key;
  if (k.empty()) return;
  if (p.side != kNoSide) {
    static const char* const kFingers[][2] = {{"thumb", nullptr}, {"index", nullptr}, {"middle", nullptr},
                                              {"ring", nullptr},  {"pinky", "little"}};
    for (int f = 0; f < 5; ++f) {
      const bool named = k.find(kFingers[f][0]) != std::string::npos ||
                         (kFingers[f][1] && k.find(kFingers[f][1]) != std::string::npos);
      if (!named) continue;
      int segment = p.number >= 1 && p.number <= 3 ? p.number - 1 : -1;
      if (k.find("proximal") != std::string::npos) segment = 0;
      if (k.find("intermediate") != std::string::npos) segment = 1;
      if (k.find("distal") != std::string::npos) segment = 2;
      if (segment >= 0) add(fingerBone(p.side, f, segment), 3);
      return;
    }
    const int s = p.side;
    if (oneOf(k, {"shoulder"})) {
      add(limbBone(s, kShoulder), 2);  // CMU: the clavicle, when no collar bone says otherwise
      add(limbBone(s, kUpperArm), 1);  // mocapbank, GAMES105: the shoulder joint itself
    } else if (oneOf(k, {"collar", "clavicle", "torsoclavicle", "collarbone"})) {
      add(limbBone(s, kShoulder), 3);
    } else if (oneOf(k, {"arm", "upperarm", "uparm"})) {
      add(limbBone(s, kUpperArm), 3);
    } else if (oneOf(k, {"forearm", "lowerarm", "elbow"})) {
      add(limbBone(s, kLowerArm), 3);
    } else if (oneOf(k, {"hand", "wrist"})) {
      add(limbBone(s, kHand), 3);
    } else if (oneOf(k, {"upleg", "upperleg", "thigh"})) {
      add(limbBone(s, kUpperLeg), 3);
    } else if (oneOf(k, {"hip"})) {
      add(limbBone(s, kUpperLeg), 1);  // GAMES105's lHip is the thigh's joint
    } else if (oneOf(k, {"leg", "lowerleg", "shin", "calf", "knee", "lowleg"})) {
      add(limbBone(s, kLowerLeg), 3);
    } else if (oneOf(k, {"foot", "ankle"})) {
      add(limbBone(s, kFoot), 3);
    } else if (oneOf(k, {"toe", "toes", "toebase", "toejoint", "ball"})) {
      add(limbBone(s, kToes), 3);
    }
    return;
  }
  if (oneOf(k, {"hips", "hip", "pelvis"})) add(HumanoidBone::Hips, 3);
  else if (oneOf(k, {"neck"})) add(HumanoidBone::Neck, 3);
  else if (oneOf(k, {"head", "torsohead"})) add(HumanoidBone::Head, 3);
}

int lowestCommonAncestor(const Skeleton& s, int a, int b) {
  std::vector<char> up(s.size(), 0);
  for (int j = a; j >= 0; j = s.parents[j]) up[j] = 1;
  for (int j = b; j >= 0; j = s.parents[j])
    if (up[j]) return j;
  return -1;
}


// The spine chain is the path from the hips (exclusive) to the joint where the arms meet
// (inclusive): one joint is the spine, two are spine and chest, three or more put the
// chest in the middle and the upper chest at the top.
bool assignSpine(const Skeleton& s, HumanoidMap& m, int hub) {
  const int hips = m[HumanoidBone::Hips];
  std::vector<int> path;
  for (int j = hub; j >= 0 && j != hips; j = s.parents[j]) path.push_back(j);
  if (path.empty() || s.parents[path.back()] != hips) return false;
  std::reverse(path.begin(), path.end());
  const int n = static_cast<int>(path.size());
  m[HumanoidBone::Spine] = path[0];
  if (n == 2) m[HumanoidBone::Chest] = path[1];
  if (n >= 3) {
    m[HumanoidBone::Chest] = path[(n - 1) / 2];
    m[HumanoidBone::UpperChest] = path[n - 1];
  }
  return true;
}

int armRoot(const HumanoidMap& m, int side) {
  const int shoulder = m[limbBone(side, kShoulder)];
  return shoulder >= 0 ? shoulder : m[limbBone(side, kUpperArm)];
}

// Each present bone of a chain lies below the previous present one.
bool chainInOrder(const Skeleton& s, const HumanoidMap& m, std::initializer_list<HumanoidBone> chain) {
  int last = -1;
  for (HumanoidBone b : chain) {
    const int j = m[b];
    if (j < 0) continue;
    if (last >= 0 && !(last != j && s.isInSubtree(j, last))) return false;
    last = j;
  }
  return true;
}

bool consistent(const Skeleton& s, const HumanoidMap& m) {
  for (int side : {kLeft, kRight}) {
    if (!chainInOrder(s, m, {limbBone(side, kShoulder), limbBone(side, kUpperArm), limbBone(side, kLowerArm),
                             limbBone(side, kHand)}))
      return false;
    if (!chainInOrder(s, m, {limbBone(side, kUpperLeg), limbBone(side, kLowerLeg), limbBone(side, kFoot),
                             limbBone(side, kToes)}))
      return false;
    for (int f = 0; f < 5; ++f)
      if (!chainInOrder(s, m, {limbBone(side, kHand), fingerBone(side, f, 0), fingerBone(side, f, 1),
                               fingerBone(side, f, 2)}))
        return false;
  }
  return true;
}

bool complete(const HumanoidMap& m) {
  for (int i = 0; i < kHumanoidBoneCount; ++i)
    if (isRequired(humanoidBone(i)) && m.joint[i] < 0) return false;
  return true;
}

// Fingers count only when both hands have some.
void dropOneSidedFingers(HumanoidMap& m) {
  bool any[2] = {false, false};
  for (int side : {kLeft, kRight})
    for (int i = 0; i < 15; ++i) any[side] = any[side] || m.joint[index(kFirstFingerBone) + side * 15 + i] >= 0;
  if (any[kLeft] && any[kRight]) return;
  for (int i = index(kFirstFingerBone); i < kHumanoidBoneCount; ++i) m.joint[i] = -1;
}

HumanoidMap byNames(const Skeleton& s) {
  std::vector<Claim> claims;
  for (int j = 0; j < s.size(); ++j) claimsOf(s.names[j], j, claims);
  // Surest names first; between equally sure ones the joint nearer the root.
  std::stable_sort(claims.begin(), claims.end(), [](const Claim& a, const Claim& b) {
    return a.score != b.score ? a.score > b.score : a.joint < b.joint;
  });
  HumanoidMap m;
  std::vector<char> used(s.size(), 0);
  for (const Claim& c : claims) {
    if (m.has(c.bone) || used[c.joint]) continue;
    m[c.bone] = c.joint;
    used[c.joint] = 1;
  }
  // The hips are where the legs meet, the spine runs up to where the arms meet.
  const int legL = m[HumanoidBone::LeftUpperLeg], legR = m[HumanoidBone::RightUpperLeg];
  if (legL >= 0 && legR >= 0) m[HumanoidBone::Hips] = lowestCommonAncestor(s, legL, legR);
  const int armL = armRoot(m, kLeft), armR = armRoot(m, kRight);
  if (m.has(HumanoidBone::Hips) && armL >= 0 && armR >= 0) {
    const int hub = lowestCommonAncestor(s, armL, armR);
    if (hub < 0 || !assignSpine(s, m, hub)) return HumanoidMap{};
    for (HumanoidBone b : {HumanoidBone::Neck, HumanoidBone::Head})
      if (m.has(b) && !(hub != m[b] && s.isInSubtree(m[b], hub))) m[b] = -1;
    if (m.has(HumanoidBone::Neck) && m.has(HumanoidBone::Head) && !(m[HumanoidBone::Neck] != m[HumanoidBone::Head] && s.isInSubtree(m[HumanoidBone::Head], m[HumanoidBone::Neck])))
      m[HumanoidBone::Neck] = -1;
  }
  if (!consistent(s, m)) return HumanoidMap{};
  return m;
}

// Topology on the rest pose, for names that say nothing (CesiumMan's "leg_joint_L_1").
struct RestShape {
  const Skeleton& s;
  std::vector<glm::vec3> pos;
  std::vector<std::vector<int>> children;
  float height = 0.0f;

  explicit RestShape(const Skeleton& skeleton) : s(skeleton), children(skeleton.size()) {
    const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
    float lo = 0.0f, hi = 0.0f;
    for (int j = 0; j < s.size(); ++j) {
      pos.push_back(glm::vec3(world[j][3]));
      if (s.parents[j] >= 0) children[s.parents[j]].push_back(j);
      lo = j == 0 ? pos[j].y : std::min(lo, pos[j].y);
      hi = j == 0 ? pos[j].y : std::max(hi, pos[j].y);
    }
    height = hi - lo;
  }
  std::vector<int> subtree(int root) const {
    std::vector<char> in(s.size(), 0);
    std::vector<int> out;
    for (int j = root; j < s.size(); ++j)
      if (j == root || (s.parents[j] >= 0 && in[s.parents[j]])) {
        in[j] = 1;
        out.push_back(j);
      }
    return out;
  }
  float minY(int root) const {
    float y = pos[root].y;
    for (int j : subtree(root)) y = std::min(y, pos[j].y);
    return y;
  }
  float maxY(int root) const {
    float y = pos[root].y;
    for (int j : subtree(root)) y = std::max(y, pos[j].y);
    return y;
  }
  float sideReach(int root, const glm::vec3& from) const {
    float r = 0.0f;
    for (int j : subtree(root)) r = std::max(r, glm::length(glm::vec2(pos[j].x - from.x, pos[j].z - from.z)));
    return r;
  }
  // From `start`, always into the child whose subtree scores best, down to a leaf.
  template <class Score>
  std::vector<int> chain(int start, Score score) const {
    std::vector<int> c{start};
    while (!children[c.back()].empty()) {
      const std::vector<int>& k = children[c.back()];
      c.push_back(*std::max_element(k.begin(), k.end(), [&](int a, int b) { return score(a) < score(b); }));
    }
    return c;
  }
};

// The first joint along `chain` that starts a long bone (longer than `share` of `reach`)
// followed at once by a second long bone: {start, middle, end} indices into the chain.
bool twoLongBones(const std::vector<glm::vec3>& p, float reach, float share, int out[3]) {
  for (size_t i = 0; i + 2 < p.size(); ++i)
    if (glm::length(p[i + 1] - p[i]) > share * reach && glm::length(p[i + 2] - p[i + 1]) > share * reach) {
      out[0] = static_cast<int>(i), out[1] = static_cast<int>(i + 1), out[2] = static_cast<int>(i + 2);
      return true;
    }
  return false;
}

HumanoidMap byTopology(const Skeleton& s) {
  HumanoidMap m;
  if (s.empty()) return m;
  const RestShape shape(s);
  const float h = shape.height;
  if (!(h > 0.0f)) return m;
  int hips = -1, upper = -1;
  std::vector<int> legs;
  for (int j = 0; j < s.size() && hips < 0; ++j) {
    std::vector<int> down, up;
    for (int c : shape.children[j]) {
      if (shape.minY(c) < shape.pos[j].y - 0.3f * h) down.push_back(c);
      else if (shape.maxY(c) > shape.pos[j].y + 0.2f * h) up.push_back(c);
    }
    if (down.size() < 2 || up.empty()) continue;
    std::sort(down.begin(), down.end(), [&](int a, int b) { return shape.minY(a) < shape.minY(b); });
    hips = j;
    legs = {down[0], down[1]};
    upper = *std::max_element(up.begin(), up.end(), [&](int a, int b) { return shape.maxY(a) < shape.maxY(b); });
  }
  if (hips < 0) return m;
  // Legs: two long bones going down (thigh, shin); the foot follows, then the toes.
  struct LimbChain { int bones[4] = {-1, -1, -1, -1}; glm::vec3 root{0.0f}; };
  LimbChain leg[2];
  glm::vec3 forward(0.0f);
  for (int i = 0; i < 2; ++i) {
    const std::vector<int> c = shape.chain(legs[i], [&](int j) { return -shape.minY(j); });
    std::vector<glm::vec3> p;
    for (int j : c) p.push_back(shape.pos[j]);
    const float reach = p.front().y - shape.minY(legs[i]);
    int at[3];
    if (!(reach > 0.0f) || !twoLongBones(p, reach, 0.25f, at)) return HumanoidMap{};
    for (int k = 0; k < 3; ++k) leg[i].bones[k] = c[at[k]];
    if (at[2] + 1 < static_cast<int>(c.size())) {
      const glm::vec3 d = p[at[2] + 1] - p[at[2]];
      forward += glm::vec3(d.x, 0.0f, d.z);
      if (!shape.children[c[at[2] + 1]].empty()) leg[i].bones[3] = c[at[2] + 1];
    }
    leg[i].root = p[at[0]];
  }
  forward = glm::length(forward) > 1e-6f * h ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, 1.0f);
  const glm::vec3 left = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), forward);
  // Arms: the first joint above the hips with two branches of three joints or more that
  // reach out sideways (hanging arms reach out less than T-posed ones, but some).
  int hub = upper;
  std::vector<int> arms;
  while (hub >= 0) {
    std::vector<int> side;
    for (int c : shape.children[hub])
      if (shape.subtree(c).size() >= 3 && shape.sideReach(c, shape.pos[hub]) > 0.05f * h) side.push_back(c);
    if (side.size() >= 2) {
      std::sort(side.begin(), side.end(), [&](int a, int b) {
        return shape.sideReach(a, shape.pos[hub]) > shape.sideReach(b, shape.pos[hub]);
      });
      arms = {side[0], side[1]};
      break;
    }
    const std::vector<int>& k = shape.children[hub];
    if (k.empty()) return HumanoidMap{};
    hub = *std::max_element(k.begin(), k.end(), [&](int a, int b) {
      return shape.subtree(a).size() < shape.subtree(b).size();
    });
  }
  if (hub < 0) return HumanoidMap{};
  LimbChain arm[2];
  for (int i = 0; i < 2; ++i) {
    const glm::vec3 from = shape.pos[hub];
    const std::vector<int> c = shape.chain(arms[i], [&](int j) { return shape.sideReach(j, from); });
    std::vector<glm::vec3> p;
    float reach = 0.0f;
    for (int j : c) {
      p.push_back(shape.pos[j]);
      reach = std::max(reach, glm::length(shape.pos[j] - p.front()));
    }
    int at[3];
    if (!(reach > 0.0f) || !twoLongBones(p, reach, 0.2f, at)) return HumanoidMap{};
    arm[i].bones[0] = at[0] > 0 ? c[at[0] - 1] : -1;  // a short bone before the arm: the clavicle
    for (int k = 0; k < 3; ++k) arm[i].bones[k + 1] = c[at[k]];
    arm[i].root = p[at[0]];
  }
  // Left and right by the side of the character each limb is on.
  const int legLeft = glm::dot(leg[0].root - shape.pos[hips], left) >= glm::dot(leg[1].root - shape.pos[hips], left) ? 0 : 1;
  const int armLeft = glm::dot(arm[0].root - shape.pos[hub], left) >= glm::dot(arm[1].root - shape.pos[hub], left) ? 0 : 1;
  for (int side : {kLeft, kRight}) {
    const LimbChain& l = leg[side == kLeft ? legLeft : 1 - legLeft];
    const LimbChain& a = arm[side == kLeft ? armLeft : 1 - armLeft];
    for (int k = 0; k < 4; ++k) {
      m[limbBone(side, static_cast<Limb>(kUpperLeg + k))] = l.bones[k];
      m[limbBone(side, static_cast<Limb>(kShoulder + k))] = a.bones[k];
    }
  }
  // Legs below arms: a humanoid's hands hang above its knees (a quadruped's front paws do not).
  for (const LimbChain& a : arm)
    for (const LimbChain& l : leg)
      if (!(shape.pos[a.bones[3]].y > shape.pos[l.bones[1]].y)) return HumanoidMap{};
  m[HumanoidBone::Hips] = hips;
  if (!assignSpine(s, m, hub)) return HumanoidMap{};
  // The head: the highest branch left at the arms' joint.
  int headStart = -1;
  for (int c : shape.children[hub])
    if (c != arms[0] && c != arms[1] && (headStart < 0 || shape.maxY(c) > shape.maxY(headStart))) headStart = c;
  if (headStart < 0) return HumanoidMap{};
  const std::vector<int> c = shape.chain(headStart, [&](int j) { return shape.maxY(j); });
  const int n = static_cast<int>(c.size());
  if (n == 1) m[HumanoidBone::Head] = c[0];
  if (n >= 2) {
    m[HumanoidBone::Neck] = c[0];
    m[HumanoidBone::Head] = n == 2 ? c[1] : c[n - 2];  // past two, the last is the head's end
  }
  return m;
}

std::vector<std::string> missingRequired(const HumanoidMap& m) {
  std::vector<std::string> out;
  for (int i = 0; i < kHumanoidBoneCount; ++i)
    if (isRequired(humanoidBone(i)) && m.joint[i] < 0) out.push_back(toString(humanoidBone(i)));
  return out;
}

}  // namespace

Result<HumanoidReading> findHumanoid(const Skeleton& skeleton) {
  HumanoidReading r;
  r.bones = byNames(skeleton);
  if (complete(r.bones)) {
    dropOneSidedFingers(r.bones);
    return r;
  }
  const std::vector<std::string> missing = missingRequired(r.bones);
  r.bones = byTopology(skeleton);
  r.source = HumanoidSource::Topology;
  if (complete(r.bones) && consistent(skeleton, r.bones)) return r;
  std::string list;
  for (size_t i = 0; i < missing.size() && i < 4; ++i) list += (i ? ", " : "") + missing[i];
  if (missing.size() > 4) list += ", ...";
  return Result<HumanoidReading>::failure(
      "no humanoid found: the joint names give no " + list +
      ", and the hierarchy has no hips with two legs below and two arms above");
}

std::string BoneMap::validate(const Skeleton& source, const Skeleton& target) const {
  std::vector<int> seenS(source.size(), -1), seenT(target.size(), -1);
  for (size_t i = 0; i < pairs.size(); ++i) {
    const BonePair& p = pairs[i];
    if (p.source < 0 || p.source >= source.size()) return "bone map pair " + std::to_string(i) + ": no such source joint";
    if (p.target < 0 || p.target >= target.size()) return "bone map pair " + std::to_string(i) + ": no such target joint";
    if (seenS[p.source] >= 0) return "source joint '" + source.names[p.source] + "' is mapped twice";
    if (seenT[p.target] >= 0) return "target joint '" + target.names[p.target] + "' is mapped twice";
    seenS[p.source] = seenT[p.target] = static_cast<int>(i);
  }
  for (const BonePair& a : pairs)
    for (const BonePair& b : pairs)
      if ((a.source != b.source && source.isInSubtree(b.source, a.source)) && (b.target != a.target && target.isInSubtree(a.target, b.target)))
        return "incompatible skeletons: source '" + source.names[a.source] + "' is above '" + source.names[b.source] +
               "' but target '" + target.names[a.target] + "' is below '" + target.names[b.target] + "'";
  return {};
}

int BoneMap::targetOf(int sourceJoint) const {
  for (const BonePair& p : pairs)
    if (p.source == sourceJoint) return p.target;
  return -1;
}

int BoneMap::sourceOf(int targetJoint) const {
  for (const BonePair& p : pairs)
    if (p.target == targetJoint) return p.source;
  return -1;
}

BoneMap mapThroughHumanoid(const HumanoidMap& source, const HumanoidMap& target) {
  HumanoidMap s = source, t = target;
  dropOneSidedFingers(s);
  dropOneSidedFingers(t);
  BoneMap map;
  for (int i = 0; i < kHumanoidBoneCount; ++i)
    if (s.joint[i] >= 0 && t.joint[i] >= 0) map.pairs.push_back({s.joint[i], t.joint[i]});
  std::sort(map.pairs.begin(), map.pairs.end(), [](const BonePair& a, const BonePair& b) { return a.target < b.target; });
  return map;
}

BoneMap mapByIdenticalNames(const Skeleton& source, const Skeleton& target) {
  BoneMap map;
  for (int j = 0; j < target.size(); ++j) {
    const int s = source.find(target.names[j]);
    if (s >= 0) map.pairs.push_back({s, j});
  }
  return map;
}

const char* humanoidRoleOf(const HumanoidMap& reading, int joint) {
  for (int i = 0; i < kHumanoidBoneCount; ++i)
    if (reading.joint[i] == joint && joint >= 0) return toString(humanoidBone(i));
  return nullptr;
}

ClipSourceMap toClipSourceMap(const BoneMap& map, const Skeleton& source, const std::string& file, int clip) {
  ClipSourceMap out;
  out.file = file;
  out.clip = clip;
  for (const BonePair& p : map.pairs) out.pairs.push_back(SourceMapPair{source.names[p.source], p.target});
  return out;
}

Result<BoneMap> fromClipSourceMap(const ClipSourceMap& kept, const Skeleton& source, const Skeleton& target) {
  BoneMap map;
  for (const SourceMapPair& p : kept.pairs) {
    const int s = source.find(p.source);
    if (s < 0) return Result<BoneMap>::failure("the saved bone map names source joint '" + p.source + "', which " +
                                               (kept.file.empty() ? std::string("the motion file") : kept.file) +
                                               " does not have");
    map.pairs.push_back(BonePair{s, p.target});
  }
  if (std::string bad = map.validate(source, target); !bad.empty())
    return Result<BoneMap>::failure("the saved bone map: " + bad);
  return map;
}

}  // namespace kinema
