#include "cli/life_demo.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/command_line.h"
#include "io/atomic_write.h"
#include "io/image.h"
#include "sim/game_of_life.h"
#include "render/raster_draw.h"

namespace kinema::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kFieldWidth = 64, kFieldHeight = 40, kGenerations = 150;

struct PlacedPattern {
  const char* name;
  int x, y;
  std::vector<std::string> rows;
};

std::vector<PlacedPattern> demoPatterns() {
  return {
      {"gosper_glider_gun", 1, 1, gosperGliderGun()},
      {"blinker", 3, 30, {"OOO"}},
      {"toad", 10, 30, {".OOO", "OOO."}},
      {"block", 18, 30, {"OO", "OO"}},
      {"beehive", 24, 30, {".OO.", "O..O", ".OO."}},
  };
}

// The field in `img` inside the pixel rectangle (x0, y0)..(x0 + w, y0 + h), with a caption.
void drawField(Image& img, const LifeGrid& grid, int generation, int x0, int y0, int w, int h) {
  const int captionHeight = 18;
  const int cell = std::max(1, std::min(w / grid.width, (h - captionHeight) / grid.height));
  const int fx = x0 + (w - cell * grid.width) / 2, fy = y0 + captionHeight;
  raster::rect(img, fx, fy, fx + cell * grid.width, fy + cell * grid.height, {245, 245, 245});
  for (int y = 0; y < grid.height; ++y)
    for (int x = 0; x < grid.width; ++x)
      if (grid.at(x, y))
        raster::rect(img, fx + x * cell, fy + y * cell, fx + (x + 1) * cell - (cell > 3 ? 1 : 0),
                     fy + (y + 1) * cell - (cell > 3 ? 1 : 0), {20, 20, 20});
  char caption[96];
  std::snprintf(caption, sizeof caption, "generation %d, %d alive", generation, grid.population());
  raster::text(img, fx, y0 + 3, caption, {40, 40, 40}, 2);
}

Image blank(int w, int h) {
  Image img(w, h);
  std::fill(img.rgba.begin(), img.rgba.end(), uint8_t(255));
  return img;
}

}  // namespace

int runLifeDemo(const std::string& outDir, int width, int height) {
  std::error_code ec;
  const fs::path out(outDir), frames = fs::path(outDir) / "frames";
  fs::create_directories(frames, ec);
  if (ec) return badInput(outDir + ": cannot create the folder (" + ec.message() + ")");
  LifeGrid grid(kFieldWidth, kFieldHeight);
  nlohmann::ordered_json patterns = nlohmann::ordered_json::array();
  for (const PlacedPattern& p : demoPatterns()) {
    stampLifePattern(grid, p.x, p.y, p.rows);
    patterns.push_back({{"name", p.name}, {"x", p.x}, {"y", p.y}});
  }
  std::cerr << "kinema demo: life: " << kFieldWidth << " x " << kFieldHeight << " cells, " << kGenerations
            << " generations...\n";
  const int snapshotAt[4] = {0, 30, 60, kGenerations};
  const int panelW = std::max(160, width / 2), panelH = std::max(120, height / 2);
  Image sheet = blank(panelW * 4, panelH);
  std::vector<int> population;
  for (int g = 0; g <= kGenerations; ++g) {
    population.push_back(grid.population());
    Image frame = blank(width, height);
    drawField(frame, grid, g, 0, 0, width, height);
    char name[32];
    std::snprintf(name, sizeof name, "gen_%03d.png", g);
    if (std::string bad = savePng((frames / name).string(), frame); !bad.empty()) return badInput(bad);
    for (int k = 0; k < 4; ++k)
      if (snapshotAt[k] == g) drawField(sheet, grid, g, k * panelW + 4, 0, panelW - 8, panelH);
    LifeStepJob step;
    step.input = &grid;
    step.edges = LifeEdges::Dead;
    step.run();
    grid = std::move(step.output);
  }
  if (std::string bad = savePng((out / "snapshots.png").string(), sheet); !bad.empty()) return badInput(bad);
  nlohmann::ordered_json j;
  j["width"] = kFieldWidth;
  j["height"] = kFieldHeight;
  j["edges"] = "dead";
  j["generations"] = kGenerations;
  j["patterns"] = std::move(patterns);
  j["population"] = population;
  if (std::string bad = writeFileAtomically((out / "numbers.json").string(), j.dump(2) + "\n"); !bad.empty())
    return badInput(bad);
  std::printf("wrote %s: frames/gen_000.png .. gen_%03d.png, snapshots.png, numbers.json\n", outDir.c_str(), kGenerations);
  return kExitOk;
}

}  // namespace kinema::cli
