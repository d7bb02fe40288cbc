#pragma once
#include "core/skeleton.h"

namespace kinema {

// Kinema's default character: a 27-joint humanoid in T-pose, Y up, facing +Z, 1.80 units
// tall, standing on y = 0 (its lowest joints, the toes, sit 2 cm up, inside the foot).
// Left-side joints end in ".L" and lie at +X (the character's left). Rest rotations are
// identity, so the rest pose is the T-pose.
Skeleton makeDefaultCharacter();

}  // namespace kinema
