#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace kinema {

// What lies beyond a Life grid's border: always-dead cells, or the opposite border (a torus).
enum class LifeEdges { Dead, Wrap };

// A binary cellular automaton's state: width x height cells, row-major from the top row,
// 1 = alive, 0 = dead.
struct LifeGrid {
  int width = 0, height = 0;
  std::vector<uint8_t> cells;

  LifeGrid() = default;
  LifeGrid(int w, int h) : width(w), height(h), cells(static_cast<size_t>(w) * h, 0) {}
  uint8_t& at(int x, int y) { return cells[static_cast<size_t>(y) * width + x]; }
  uint8_t at(int x, int y) const { return cells[static_cast<size_t>(y) * width + x]; }
  int population() const;
  bool operator==(const LifeGrid& o) const { return width == o.width && height == o.height && cells == o.cells; }
  // Empty when 1 <= width, height <= 65536, cells has width * height values of 0 or 1.
  std::string validate() const;
};

// Places a pattern written as rows of text ('O', '*' or '#' alive, anything else dead) with
// its top-left corner at (x, y); cells falling outside the grid are dropped.
void stampLifePattern(LifeGrid& grid, int x, int y, const std::vector<std::string>& rows);

// One generation of Conway's Game of Life, the seed's rules (chapter 003, 16.6): a dead cell
// with exactly three live neighbours (of its eight) comes alive; a live cell with two or three
// stays alive; every other cell dies or stays dead. All cells change at once.
struct LifeStepJob {
  const LifeGrid* input = nullptr;
  LifeEdges edges = LifeEdges::Dead;
  LifeGrid output;  // same size as the input (must not be the input)

  std::string validate() const;
  bool run();
};

// The Gosper glider gun (period 30, one glider per period), 36 x 9 cells.
const std::vector<std::string>& gosperGliderGun();

}  // namespace kinema
