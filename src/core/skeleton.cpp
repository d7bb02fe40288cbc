#include "core/skeleton.h"

#include <unordered_map>
#include <vector>

namespace kinema {

int Skeleton::addJoint(const std::string& name, int parent, const Transform& restLocal) {
  names.push_back(name);
  parents.push_back(parent);
  rest.push_back(restLocal);
  return size() - 1;
}

int Skeleton::find(const std::string& name) const {
  for (int i = 0; i < size(); ++i)
    if (names[i] == name) return i;
  return -1;
}

std::string Skeleton::validate() const {
  const size_t n = parents.size();
  if (names.size() != n || rest.size() != n)
    return "skeleton arrays differ in size (" + std::to_string(names.size()) + " names, " +
           std::to_string(n) + " parents, " + std::to_string(rest.size()) + " rest transforms)";
  std::unordered_map<std::string, int> seen;
  for (size_t i = 0; i < n; ++i) {
    const std::string where = "joint " + std::to_string(i);
    if (names[i].empty()) return where + " has an empty name";
    auto [it, inserted] = seen.emplace(names[i], static_cast<int>(i));
    if (!inserted)
      return where + " '" + names[i] + "' has the same name as joint " + std::to_string(it->second);
    const int p = parents[i];
    if (p < -1 || p >= static_cast<int>(n))
      return where + " '" + names[i] + "' has parent index " + std::to_string(p) +
             ", outside -1.." + std::to_string(static_cast<long>(n) - 1);
    if (!rest[i].isFinite()) return where + " '" + names[i] + "' has a non-finite rest transform";
  }
  // Cycles first (they are the real error), then order. Each joint is walked up once:
  // 1 marks the path being walked, 2 a joint known to reach a root.
  std::vector<char> state(n, 0);
  std::vector<int> path;
  for (size_t i = 0; i < n; ++i) {
    path.clear();
    int j = static_cast<int>(i);
    while (j != -1 && state[j] == 0) {
      state[j] = 1;
      path.push_back(j);
      j = parents[j];
    }
    if (j != -1 && state[j] == 1)
      return "joint " + std::to_string(j) + " '" + names[j] + "' is its own ancestor (cycle)";
    for (int k : path) state[k] = 2;
  }
  for (size_t i = 0; i < n; ++i)
    if (parents[i] >= static_cast<int>(i))
      return "joint " + std::to_string(i) + " '" + names[i] + "' comes before its parent " +
             std::to_string(parents[i]) + " (parents must be listed first)";
  return {};
}

bool Skeleton::isInSubtree(int joint, int ancestor) const {
  for (int j = joint; j >= 0; j = parents[j])
    if (j == ancestor) return true;
  return false;
}

}  // namespace kinema
