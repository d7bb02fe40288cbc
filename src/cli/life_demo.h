#pragma once
#include <string>

namespace kinema::cli {

// `kinema demo life --out DIR [--size WxH]`: Conway's Game of Life with the seed's rules
// (sim/game_of_life.h) on a 64 x 40 field with dead edges, seeded with a Gosper glider
// gun, a blinker, a toad, a block and a beehive; 150 generations. Writes frames/gen_NNN.png
// (one per generation, width x height pixels), snapshots.png (generations 0, 30, 60, 150 side
// by side, as the seed's figure 16.26) and numbers.json (field, patterns, population per
// generation).
int runLifeDemo(const std::string& out, int width, int height);

}  // namespace kinema::cli
