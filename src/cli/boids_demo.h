#pragma once
#include <string>

namespace kinema::cli {

// `kinema demo boids --out DIR [--size WxH]`: the seed's figure 16.28 re-run. A planar flock of
// 60 members crosses a field with a round obstacle and a box towards a goal, twice: with the
// priority acceleration allocation and with the naive average (sim/boids.h). Writes
// priority.png and average.png (top view at 5.5 s: the last 2 s of each member's path, the
// obstacles, and the impulses of the member avoiding hardest: what each asked (thin) and what
// the allocation granted (thick))
// and numbers.json (per mode: closest approach of two members, steps with a member inside an
// obstacle, mean speed, members that reached the goal area).
int runBoidsDemo(const std::string& out, int width, int height);

}  // namespace kinema::cli
