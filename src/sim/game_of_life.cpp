#include "sim/game_of_life.h"

namespace kinema {

int LifeGrid::population() const {
  int n = 0;
  for (uint8_t c : cells) n += c;
  return n;
}

std::string LifeGrid::validate() const {
  if (width < 1 || height < 1 || width > 65536 || height > 65536)
    return "a Life grid needs 1 to 65536 cells a side, found " + std::to_string(width) + " x " + std::to_string(height);
  if (cells.size() != static_cast<size_t>(width) * height) return "a Life grid's cells do not match its size";
  for (uint8_t c : cells)
    if (c > 1) return "a Life cell holds a value other than 0 or 1";
  return "";
}

void stampLifePattern(LifeGrid& grid, int x, int y, const std::vector<std::string>& rows) {
  for (int r = 0; r < static_cast<int>(rows.size()); ++r)
    for (int c = 0; c < static_cast<int>(rows[r].size()); ++c) {
      const int gx = x + c, gy = y + r;
      if (gx < 0 || gy < 0 || gx >= grid.width || gy >= grid.height) continue;
      const char ch = rows[r][c];
      grid.at(gx, gy) = (ch == 'O' || ch == '*' || ch == '#') ? 1 : 0;
    }
}

std::string LifeStepJob::validate() const {
  if (!input) return "no input grid";
  if (input == &output) return "the output must not be the input (all cells change at once)";
  return input->validate();
}

bool LifeStepJob::run() {
  if (!validate().empty()) return false;
  const LifeGrid& in = *input;
  const int w = in.width, h = in.height;
  output = LifeGrid(w, h);
  const bool wrap = edges == LifeEdges::Wrap;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int live = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0) continue;
          int nx = x + dx, ny = y + dy;
          if (wrap) {
            nx = (nx + w) % w;
            ny = (ny + h) % h;
          } else if (nx < 0 || ny < 0 || nx >= w || ny >= h) {
            continue;
          }
          live += in.at(nx, ny);
        }
      output.at(x, y) = in.at(x, y) ? (live == 2 || live == 3) : (live == 3);
    }
  return true;
}

const std::vector<std::string>& gosperGliderGun() {
  static const std::vector<std::string> gun = {
      "........................O...........",
      "......................O.O...........",
      "............OO......OO............OO",
      "...........O...O....OO............OO",
      "OO........O.....O...OO..............",
      "OO........O...O.OO....O.O...........",
      "..........O.....O.......O...........",
      "...........O...O....................",
      "............OO......................",
  };
  return gun;
}

}  // namespace kinema
