#include "editor/model/edit_labels.h"

namespace kinema {

std::string jointsPhrase(const Skeleton& skeleton, const std::vector<int>& joints) {
  auto name = [&](int j) {
    return j >= 0 && j < skeleton.size() ? skeleton.names[j] : "joint " + std::to_string(j);
  };
  if (joints.empty()) return "no joints";
  if (joints.size() == 1) return name(joints[0]);
  if (joints.size() == 2) return name(joints[0]) + " and " + name(joints[1]);
  return std::to_string(joints.size()) + " joints";
}

std::string countPhrase(size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many.empty() ? one + "s" : many);
}

}  // namespace kinema
