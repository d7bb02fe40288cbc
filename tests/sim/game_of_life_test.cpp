// Conway's Game of Life (the seed's rules) and `kinema demo life`.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/image.h"
#include "sim/game_of_life.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

LifeGrid step(const LifeGrid& g, LifeEdges edges = LifeEdges::Dead) {
  LifeStepJob job;
  job.input = &g;
  job.edges = edges;
  EXPECT_TRUE(job.run());
  return job.output;
}

LifeGrid field(int w, int h, int x, int y, const std::vector<std::string>& rows) {
  LifeGrid g(w, h);
  stampLifePattern(g, x, y, rows);
  return g;
}

TEST(GameOfLife, TheSeedsThreeRulesCellByCell) {
  // A dead centre with exactly 3 live neighbours is born; with 2 or 4 it stays dead.
  EXPECT_EQ(step(field(3, 3, 0, 0, {"O.O", "...", ".O."})).at(1, 1), 1);
  EXPECT_EQ(step(field(3, 3, 0, 0, {"O.O", "...", "..."})).at(1, 1), 0);
  EXPECT_EQ(step(field(3, 3, 0, 0, {"O.O", "...", "O.O"})).at(1, 1), 0);
  // A live centre survives with 2 or 3, dies with 0, 1 (loneliness) or 4 (crowding).
  EXPECT_EQ(step(field(3, 3, 0, 0, {"O..", ".O.", "..O"})).at(1, 1), 1);
  EXPECT_EQ(step(field(3, 3, 0, 0, {"O.O", ".O.", "..O"})).at(1, 1), 1);
  EXPECT_EQ(step(field(3, 3, 0, 0, {"...", ".O.", "..."})).at(1, 1), 0);
  EXPECT_EQ(step(field(3, 3, 0, 0, {"O..", ".O.", "..."})).at(1, 1), 0);
  EXPECT_EQ(step(field(3, 3, 0, 0, {"O.O", ".O.", "O.O"})).at(1, 1), 0);
}

TEST(GameOfLife, BlockStaysBlinkerHasPeriodTwo) {
  const LifeGrid block = field(6, 6, 2, 2, {"OO", "OO"});
  EXPECT_EQ(step(block), block);
  const LifeGrid blinker = field(5, 5, 1, 2, {"OOO"});
  const LifeGrid vertical = field(5, 5, 2, 1, {"O", "O", "O"});
  EXPECT_EQ(step(blinker), vertical);
  EXPECT_EQ(step(step(blinker)), blinker);
}

TEST(GameOfLife, GliderMovesOneCellDiagonallyEveryFourGenerations) {
  const std::vector<std::string> glider = {".O.", "..O", "OOO"};  // heads down-right
  for (LifeEdges edges : {LifeEdges::Dead, LifeEdges::Wrap}) {
    LifeGrid g = field(12, 12, 1, 1, glider);
    for (int period = 1; period <= 3; ++period) {
      for (int k = 0; k < 4; ++k) g = step(g, edges);
      EXPECT_EQ(g, field(12, 12, 1 + period, 1 + period, glider)) << "after " << 4 * period << " generations";
    }
  }
  // On a torus it comes back where it started after crossing the whole field (8 x 4 generations).
  LifeGrid g = field(8, 8, 1, 1, glider);
  const LifeGrid start = g;
  for (int k = 0; k < 32; ++k) g = step(g, LifeEdges::Wrap);
  EXPECT_EQ(g, start);
}

TEST(GameOfLife, GosperGunFiresOneGliderEveryThirtyGenerations) {
  LifeGrid g = field(70, 50, 1, 1, gosperGliderGun());
  EXPECT_EQ(g.population(), 36);  // the gun's own cell count
  std::vector<int> population;
  for (int k = 0; k <= 120; ++k) {
    population.push_back(g.population());
    g = step(g);
  }
  // Once the first glider has left, each period of 30 adds one glider of 5 cells (the gun
  // repeats itself and the gliders fly on without meeting anything on this field).
  for (int k = 30; k + 30 <= 120; k += 10) EXPECT_EQ(population[k + 30], population[k] + 5) << k;
}

TEST(GameOfLife, DemoWritesFramesSnapshotsAndPopulation) {
  const std::string dir = test::makeTempDir();
  std::string out, err;
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " demo life --out " + dir + " --size 320x240", &out, &err), 0)
      << err;
  const nlohmann::json j = nlohmann::json::parse(test::readFile(dir + "/numbers.json"));
  ASSERT_EQ(j["population"].size(), 151u);
  // Gun 36, blinker 3, toad 6, block 4, beehive 6 at the start.
  EXPECT_EQ(j["population"][0], 36 + 3 + 6 + 4 + 6);
  EXPECT_TRUE(std::filesystem::exists(dir + "/frames/gen_150.png"));
  Result<Image> sheet = loadPng(dir + "/snapshots.png");
  ASSERT_TRUE(sheet.ok());
  EXPECT_EQ(sheet->width, 4 * 160);
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " demo list", &out, &err), 0);
  EXPECT_NE(out.find("life"), std::string::npos);
}

}  // namespace
}  // namespace kinema
