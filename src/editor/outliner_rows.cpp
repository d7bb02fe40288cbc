#include "editor/outliner_rows.h"

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
  // hidden[i]: some ancestor of i is collapsed (ignored while searching).
  std::vector<char> hidden(n, 0);
  std::vector<OutlinerRow> rows;
  for (int i = 0; i < n; ++i) {
    const int p = skeleton.parents[i];
    if (search.empty() && p >= 0)
      hidden[i] = hidden[p] || (p < static_cast<int>(collapsed.size()) && collapsed[p]);
    if (!keep[i] || hidden[i]) continue;
    rows.push_back({i, depth[i], hasChildren[i] != 0, search.empty() || matches[i] != 0});
  }
  return rows;
}

}  // namespace kinema
