#pragma once
// What the .kinema file's sections (io/kinema_file_*.cpp) share: a reader that names the JSON
// path of every value it rejects, and the codecs of numbers, joint names and transforms.
// Internal to io/; callers use io/kinema_file.h.
#include <climits>
#include <cmath>
#include <string>
#include <unordered_map>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "core/skeleton.h"
#include "io/input_limits.h"
#include "io/message_text.h"

namespace kinema::kinema_format {

using Json = nlohmann::ordered_json;

// Doubles at or beyond 2^128 - 2^103 (halfway between FLT_MAX and the next power of two)
// round to infinity as floats; everything below rounds to a finite float.
extern const double kFloatOverflow;

// A JSON array of `n` floats, each written as the shortest text that reads back exactly.
Json vec(const float* v, int n);

// Reads with the JSON path of every value at hand, so errors can point at it.
class Reader {
 public:
  explicit Reader(std::string source, const InputLimits& limits = {}, size_t inputBytes = 0)
      : limits(limits), imageBytesLeft(imageBudgetBytes(inputBytes, limits)), source_(std::move(source)) {}
  const std::string& error() const { return error_; }
  const InputLimits limits;
  size_t imageBytesLeft;  // decoded images still allowed (InputLimits::imageBytesOverFileSize)
  // Joint name -> index, filled as the skeleton is read: lookups by name stay constant time
  // (Skeleton::find is a linear scan, quadratic over a 200,000-joint file).
  std::unordered_map<std::string, int> jointIndex;
  int joint(const Skeleton& s, const std::string& name) const {
    if (jointIndex.size() != static_cast<size_t>(s.size())) return s.find(name);  // another skeleton
    const auto it = jointIndex.find(name);
    return it == jointIndex.end() ? -1 : it->second;
  }

  bool fail(const std::string& path, const std::string& what) {
    error_ = oneLineMessage(source_ + ": " + (path.empty() ? "" : path + ": ") + what);
    return false;
  }

  const Json* member(const Json& obj, const std::string& path, const char* key, bool required) {
    const std::string p = path.empty() ? key : path + "." + key;
    auto it = obj.find(key);
    if (it == obj.end()) {
      if (required) fail(p, "missing");
      return nullptr;
    }
    return &*it;
  }

  bool number(const Json& j, const std::string& path, double& out) {
    if (!j.is_number()) return fail(path, "expected a number, found " + std::string(j.type_name()));
    out = j.get<double>();
    if (!std::isfinite(out)) return fail(path, "not a finite number");
    return true;
  }

  bool floats(const Json& j, const std::string& path, int n, float* out) {
    if (!j.is_array() || static_cast<int>(j.size()) != n)
      return fail(path, "expected an array of " + std::to_string(n) + " numbers");
    for (int i = 0; i < n; ++i) {
      double v = 0.0;
      if (!number(j[i], path + "[" + std::to_string(i) + "]", v)) return false;
      if (std::abs(v) >= kFloatOverflow) return fail(path + "[" + std::to_string(i) + "]", "number out of float range");
      out[i] = static_cast<float>(v);
    }
    return true;
  }

  bool string(const Json& j, const std::string& path, std::string& out) {
    if (!j.is_string()) return fail(path, "expected a string, found " + std::string(j.type_name()));
    out = j.get<std::string>();
    return true;
  }

  bool integer(const Json& j, const std::string& path, long long& out) {
    if (!j.is_number_integer()) return fail(path, "expected an integer, found " + std::string(j.type_name()));
    // Unsigned values above LLONG_MAX would wrap (2^64 - 1 would read as -1).
    if (j.is_number_unsigned() && j.get<unsigned long long>() > static_cast<unsigned long long>(LLONG_MAX))
      return fail(path, "integer " + std::to_string(j.get<unsigned long long>()) + " is out of range");
    out = j.get<long long>();
    return true;
  }

 private:
  std::string source_;
  std::string error_;
};

// Normalise only quaternions that are visibly off unit length, so a saved unit
// quaternion reads back bit for bit.
glm::quat normalizeIfNeeded(const glm::quat& q);
// The optional "translation", "rotation" ([x, y, z, w], normalised) and "scale" members of a
// joint or pose entry at `p`, over what `t` holds.
bool readTransform(Reader& r, const Json& j, const std::string& p, Transform& t);
// The transform's members as readTransform reads them, into `j`.
void writeTransform(const Transform& t, Json& j);
// obj[key], a joint's name, as its index in `s` (left alone when absent and not required).
bool readJointName(Reader& r, const Json& obj, const std::string& p, const char* key, const Skeleton& s,
                   bool required, int& out);
// A finite number in float range.
bool readFloat(Reader& r, const Json& j, const std::string& path, float& out);

// An enum named by a string, with the list of accepted names in the error.
template <typename E>
bool readEnum(Reader& r, const Json& j, const std::string& path, E& out, const char* accepted) {
  std::string text;
  if (!r.string(j, path, text)) return false;
  if (!fromString(text, out)) return r.fail(path, "'" + cutForMessage(text) + "' is not one of " + accepted);
  return true;
}

}  // namespace kinema::kinema_format
