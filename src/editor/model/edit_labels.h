#pragma once
#include <string>
#include <vector>

#include "core/skeleton.h"

namespace kinema {

// The undo history's labels share one style: a verb, what it acted on, then where or to
// what ("Rotate LowerArm.L", "Rotate 3 joints", "Insert keys on Hand.L at frame 12",
// "Set frame rate to 30 fps"); joint names as the skeleton spells them, the rest in lower
// case after the verb.

// "Hand.L"; "Hand.L and Hand.R"; "3 joints" (more than two); "no joints".
std::string jointsPhrase(const Skeleton& skeleton, const std::vector<int>& joints);
// "1 key", "4 keys" (`many` is `one` + "s" when empty).
std::string countPhrase(size_t n, const std::string& one, const std::string& many = "");

}  // namespace kinema
