#include "deform/deformer_stack.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/math.h"

namespace kinema {
namespace {

// "point.12.y" -> 12, 1; false when the name is not a lattice point parameter.
bool parsePointParameter(const std::string& name, int& point, int& component) {
  if (name.rfind("point.", 0) != 0 || name.size() < 9) return false;
  const size_t dot = name.find('.', 6);
  if (dot == std::string::npos || dot + 2 != name.size() || dot == 6) return false;
  for (size_t i = 6; i < dot; ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  if (dot - 6 > 6) return false;
  point = std::atoi(name.substr(6, dot - 6).c_str());
  const char c = name[dot + 1];
  if (c < 'x' || c > 'z') return false;
  component = c - 'x';
  return true;
}

bool parseOffsetParameter(const std::string& name, int& component) {
  if (name.size() != 8 || name.rfind("offset.", 0) != 0) return false;
  const char c = name[7];
  if (c < 'x' || c > 'z') return false;
  component = c - 'x';
  return true;
}

}  // namespace

const char* toString(DeformerType type) {
  switch (type) {
    case DeformerType::Lattice: return "lattice";
    case DeformerType::Bend: return "bend";
    case DeformerType::Twist: return "twist";
    case DeformerType::Taper: return "taper";
    case DeformerType::SoftPull: return "soft_pull";
  }
  return "lattice";
}

bool fromString(const std::string& s, DeformerType& out) {
  for (DeformerType t : {DeformerType::Lattice, DeformerType::Bend, DeformerType::Twist, DeformerType::Taper,
                         DeformerType::SoftPull})
    if (s == toString(t)) {
      out = t;
      return true;
    }
  return false;
}

std::string Deformer::validate(int jointCount) const {
  if (parentJoint < -1 || parentJoint >= jointCount)
    return "parent joint " + std::to_string(parentJoint) + " is not a joint of the skeleton";
  if (!isFinite(parentRest) || std::abs(glm::determinant(glm::mat3(parentRest))) < 1e-12f)
    return "parent rest matrix is not an invertible finite transform";
  for (size_t p = 0; p < weights.size(); ++p)
    for (size_t v = 0; v < weights[p].size(); ++v)
      if (!(weights[p][v] >= 0.0f && weights[p][v] <= 1.0f))
        return "weight " + std::to_string(v) + " of primitive " + std::to_string(p) + " is not in [0, 1]";
  switch (type) {
    case DeformerType::Lattice: return lattice.validate();
    case DeformerType::Bend:
    case DeformerType::Twist:
    case DeformerType::Taper: {
      const AxisDeformerKind want = type == DeformerType::Bend    ? AxisDeformerKind::Bend
                                    : type == DeformerType::Twist ? AxisDeformerKind::Twist
                                                                  : AxisDeformerKind::Taper;
      if (axis.kind != want) return "axis deformer kind does not match the deformer's type";
      return axis.validate();
    }
    case DeformerType::SoftPull: return pull.validate();
  }
  return "unknown deformer type";
}

const Deformer* DeformerStack::find(const std::string& name) const {
  for (const Deformer& d : deformers)
    if (d.name == name) return &d;
  return nullptr;
}

Deformer* DeformerStack::find(const std::string& name) {
  for (Deformer& d : deformers)
    if (d.name == name) return &d;
  return nullptr;
}

std::string DeformerStack::validate(const Mesh& mesh, int jointCount) const {
  for (size_t i = 0; i < deformers.size(); ++i) {
    const Deformer& d = deformers[i];
    const std::string at = "deformer " + std::to_string(i) + " ('" + d.name + "'): ";
    if (d.name.empty()) return at + "a deformer needs a name";
    if (d.name.find('/') != std::string::npos) return at + "a deformer's name may not contain '/'";
    for (size_t k = 0; k < i; ++k)
      if (deformers[k].name == d.name) return at + "the name is used by deformer " + std::to_string(k) + " too";
    if (std::string e = d.validate(jointCount); !e.empty()) return at + e;
    if (d.weights.size() > mesh.primitives.size())
      return at + "weights for " + std::to_string(d.weights.size()) + " primitives, the mesh has " +
             std::to_string(mesh.primitives.size());
    for (size_t p = 0; p < d.weights.size(); ++p)
      if (!d.weights[p].empty() && d.weights[p].size() != mesh.primitives[p].positions.size())
        return at + std::to_string(d.weights[p].size()) + " weights for primitive " + std::to_string(p) + "'s " +
               std::to_string(mesh.primitives[p].positions.size()) + " vertices";
  }
  return "";
}

std::vector<std::string> deformerParameters(const Deformer& d) {
  std::vector<std::string> names;
  switch (d.type) {
    case DeformerType::Bend:
    case DeformerType::Twist: names = {"angle"}; break;
    case DeformerType::Taper: names = {"factor"}; break;
    case DeformerType::SoftPull: names = {"offset.x", "offset.y", "offset.z"}; break;
    case DeformerType::Lattice:
      for (size_t p = 0; p < d.lattice.points.size(); ++p)
        for (const char* c : {".x", ".y", ".z"}) names.push_back("point." + std::to_string(p) + c);
      break;
  }
  return names;
}

bool getDeformerParameter(const Deformer& d, const std::string& name, float& value) {
  int point = 0, component = 0;
  switch (d.type) {
    case DeformerType::Bend:
    case DeformerType::Twist:
      if (name != "angle") return false;
      value = d.axis.amount;
      return true;
    case DeformerType::Taper:
      if (name != "factor") return false;
      value = d.axis.amount;
      return true;
    case DeformerType::SoftPull:
      if (!parseOffsetParameter(name, component)) return false;
      value = d.pull.offset[component];
      return true;
    case DeformerType::Lattice:
      if (!parsePointParameter(name, point, component) || point >= static_cast<int>(d.lattice.points.size()))
        return false;
      value = d.lattice.points[point][component];
      return true;
  }
  return false;
}

bool setDeformerParameter(Deformer& d, const std::string& name, float value) {
  float* slot = nullptr;
  int point = 0, component = 0;
  switch (d.type) {
    case DeformerType::Bend:
    case DeformerType::Twist:
      if (name == "angle") slot = &d.axis.amount;
      break;
    case DeformerType::Taper:
      if (name == "factor") slot = &d.axis.amount;
      break;
    case DeformerType::SoftPull:
      if (parseOffsetParameter(name, component)) slot = &d.pull.offset[component];
      break;
    case DeformerType::Lattice:
      if (parsePointParameter(name, point, component) && point < static_cast<int>(d.lattice.points.size()))
        slot = &d.lattice.points[point][component];
      break;
  }
  if (!slot || !std::isfinite(value)) return false;
  *slot = value;
  return true;
}

glm::mat4 deformerFrame(const Deformer& d, const std::vector<glm::mat4>* world) {
  if (d.parentJoint < 0 || !world || d.parentJoint >= static_cast<int>(world->size())) return glm::mat4(1.0f);
  return (*world)[d.parentJoint] * glm::inverse(d.parentRest);
}

std::string DeformerStackJob::validate() const {
  if (!stack) return "DeformerStackJob: no stack";
  if (count < 0) return "DeformerStackJob: negative vertex count";
  if (count > 0 && (!positions || !outPositions)) return "DeformerStackJob: positions and outPositions are needed";
  if (primitive < 0) return "DeformerStackJob: negative primitive";
  const int joints = world ? static_cast<int>(world->size()) : 0;
  for (size_t i = 0; i < stack->deformers.size(); ++i) {
    const Deformer& d = stack->deformers[i];
    if (std::string e = d.validate(joints); !e.empty())
      return "DeformerStackJob: deformer " + std::to_string(i) + " ('" + d.name + "'): " + e;
    if (primitive < static_cast<int>(d.weights.size()) && !d.weights[primitive].empty() &&
        static_cast<int>(d.weights[primitive].size()) != count)
      return "DeformerStackJob: deformer " + std::to_string(i) + " has " +
             std::to_string(d.weights[primitive].size()) + " weights for " + std::to_string(count) + " vertices";
  }
  return "";
}

bool DeformerStackJob::run() const {
  if (!validate().empty()) return false;
  if (outPositions != positions)
    for (int v = 0; v < count; ++v) outPositions[v] = positions[v];
  for (const Deformer& d : stack->deformers) {
    if (!d.enabled) continue;
    const float* weights = primitive < static_cast<int>(d.weights.size()) && !d.weights[primitive].empty()
                               ? d.weights[primitive].data()
                               : nullptr;
    const glm::mat4 frame = deformerFrame(d, world);
    if (d.type == DeformerType::Lattice) {
      FfdJob job;
      job.lattice = &d.lattice;
      job.positions = outPositions;
      job.count = count;
      job.weights = weights;
      job.frame = frame;
      job.outPositions = outPositions;
      if (!job.run()) return false;
      continue;
    }
    const bool identity = frame == glm::mat4(1.0f);
    const glm::mat4 toLocal = identity ? frame : glm::inverse(frame);
    for (int v = 0; v < count; ++v) {
      const glm::vec3 p = outPositions[v];
      const glm::vec3 q = identity ? p : glm::vec3(toLocal * glm::vec4(p, 1.0f));
      const glm::vec3 moved = d.type == DeformerType::SoftPull ? applySoftPull(d.pull, q) : applyAxisDeformer(d.axis, q);
      const glm::vec3 target = identity ? moved : glm::vec3(frame * glm::vec4(moved, 1.0f));
      outPositions[v] = weights ? p + weights[v] * (target - p) : target;
    }
  }
  return true;
}

void computeVertexNormals(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices,
                          std::vector<glm::vec3>& normals) {
  normals.assign(positions.size(), glm::vec3(0.0f));
  const size_t n = positions.size();
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    if (a >= n || b >= n || c >= n) continue;
    // The cross product's length is twice the triangle's area: bigger faces weigh more.
    const glm::vec3 face = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
    normals[a] += face;
    normals[b] += face;
    normals[c] += face;
  }
  for (glm::vec3& nrm : normals) {
    const float len = glm::length(nrm);
    nrm = len > 0.0f && std::isfinite(len) ? nrm / len : glm::vec3(0, 1, 0);
  }
}

MorphTarget shapeFromDeformation(const std::vector<glm::vec3>& before, const std::vector<glm::vec3>& after,
                                 const std::vector<uint32_t>& indices) {
  MorphTarget target;
  const size_t n = std::min(before.size(), after.size());
  target.positionDeltas.resize(n);
  for (size_t v = 0; v < n; ++v) target.positionDeltas[v] = after[v] - before[v];
  if (!indices.empty()) {
    std::vector<glm::vec3> n0, n1;
    computeVertexNormals(before, indices, n0);
    computeVertexNormals(after, indices, n1);
    target.normalDeltas.resize(n);
    for (size_t v = 0; v < n; ++v) target.normalDeltas[v] = n1[v] - n0[v];
  }
  return target;
}

}  // namespace kinema
