#pragma once
#include <string>
#include <vector>

#include "core/skeleton.h"

namespace kinema {

// One line of the outliner: a joint at its depth in the tree.
struct OutlinerRow {
  int joint = -1;
  int depth = 0;
  bool hasChildren = false;
  bool matches = false;  // the joint's own name matches the search (ancestors shown for context do not)
};

// The outliner's rows in depth-first order (each joint right under its parent's subtree
// line, siblings in skeleton order).
// `search` keeps the joints whose names contain it (case-insensitive) plus their
// ancestors; an empty search keeps everything. `collapsed` (indexed by joint, may be
// shorter than the skeleton) hides a joint's descendants, except while searching, where
// every match must stay reachable.
std::vector<OutlinerRow> outlinerRows(const Skeleton& skeleton, const std::string& search,
                                      const std::vector<bool>& collapsed);

// Case-insensitive (ASCII) substring test; an empty needle matches everything.
bool containsIgnoringCase(const std::string& haystack, const std::string& needle);

}  // namespace kinema
