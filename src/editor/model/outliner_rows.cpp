#include "editor/model/outliner_rows.h"

#include <algorithm>
#include <cctype>

namespace kinema {

bool containsIgnoringCase(const std::string& haystack, const std::string& needle) {
  const auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const auto it = std::search(haystack.begin(), haystack.end(), needle.begin(), needle.end(),
                              [&](char a, char b) { return lower(a) == lower(b); });
  return it != haystack.end() || needle.empty();
}

std::vector<OutlinerRow> outlinerRows(const Skeleton& skeleton, const std::string& search,
                                      const std::vector<bool>& collapsed) {
  const int n = skeleton.size();
  std::vector<int> depth(n, 0);
  std::vector<char> hasChildren(n, 0), matches(n, 0), keep(n, search.empty() ? 1 : 0);
  for (int i = 0; i < n; ++i) {
    const int p = skeleton.parents[i];
    if (p >= 0) {
      depth[i] = depth[p] + 1;
      hasChildren[p] = 1;
    }
    matches[i] = containsIgnoringCase(skeleton.names[i], search) ? 1 : 0;
  }
  if (!search.empty()) {
    // Children come after parents, so walking backwards carries "keep" up to every ancestor.
    for (int i = n - 1; i >= 0; --i) {
      if (matches[i]) keep[i] = 1;
      if (keep[i] && skeleton.parents[i] >= 0) keep[skeleton.parents[i]] = 1;
    }
  }
  // Depth-first order, so every joint sits under its parent even when the skeleton lists a
  // parent's later children after other subtrees. An explicit stack: no recursion depth
  // that a file controls.
  std::vector<std::vector<int>> children(n);
  std::vector<int> stack;
  for (int i = n - 1; i >= 0; --i) {
    if (skeleton.parents[i] >= 0) children[skeleton.parents[i]].push_back(i);
    else stack.push_back(i);
  }
  std::vector<OutlinerRow> rows;
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    if (!keep[i]) continue;
    rows.push_back({i, depth[i], hasChildren[i] != 0, search.empty() || matches[i] != 0});
    // A collapsed joint hides its subtree, except while searching (matches stay reachable).
    if (search.empty() && i < static_cast<int>(collapsed.size()) && collapsed[i]) continue;
    // children[i] was filled from the highest index down: pushing it as is pops the lowest first.
    for (int c : children[i]) stack.push_back(c);
  }
  return rows;
}

}  // namespace kinema
