// `kinema demo`: the presets' figures and numbers, and that they replay under `kinema ik`.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "ik/solver_comparison.h"
#include "io/image.h"
#include "render/solver_figure.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using Json = nlohmann::json;
namespace fs = std::filesystem;

int kinema(const std::string& args, std::string* out = nullptr, std::string* err = nullptr) {
  return test::runCommand(std::string(KINEMA_BINARY) + " " + args, out, err);
}

TEST(DemoCommand, ListsThePresets) {
  std::string out;
  ASSERT_EQ(kinema("demo list", &out), 0);
  for (const TeachingCase& c : teachingPresets()) EXPECT_NE(out.find(c.name), std::string::npos) << c.name;
  ASSERT_EQ(kinema("demo list --json", &out), 0);
  const Json list = Json::parse(out);
  // Every IK preset first, then the four figure demos, each saying which kind it is.
  ASSERT_EQ(list.size(), teachingPresets().size() + 4);
  EXPECT_EQ(list[0]["name"], teachingPresets()[0].name);
  EXPECT_EQ(list[0]["title"], teachingPresets()[0].title);
  std::vector<std::string> figures;
  for (size_t i = 0; i < list.size(); ++i) {
    if (i < teachingPresets().size()) {
      EXPECT_EQ(list[i]["kind"], "ik-preset") << i;
    } else {
      EXPECT_EQ(list[i]["kind"], "figure") << i;
      figures.push_back(list[i]["name"]);
    }
  }
  EXPECT_EQ(figures, (std::vector<std::string>{"solver-table", "stiff-springs", "boids", "life"}));
  for (const std::string& f : figures) EXPECT_NE(out.find(f), std::string::npos) << f;
}

TEST(DemoCommand, EditCompareTakesTheIkPresetsAndRefusesFigureDemos) {
  std::string out, err;
  // A figure demo is listed by `demo list` but is no solver comparison: usage error, one line.
  EXPECT_EQ(kinema("edit --compare stiff-springs --frame-count 1", &out, &err), 2);
  EXPECT_NE(err.find("stiff-springs"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

TEST(DemoCommand, UnknownPresetIsBadInputAndBadFlagsAreUsage) {
  std::string out, err;
  const std::string dir = test::makeTempDir();
  EXPECT_EQ(kinema("demo no-such-case --out " + dir, &out, &err), 1);
  EXPECT_NE(err.find("ccd-steps"), std::string::npos) << err;  // the line lists the names
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_EQ(kinema("demo ccd-steps --out " + dir + " --bogus", &out, &err), 2);
  EXPECT_EQ(kinema("demo ccd-steps --out " + dir + " --size big", &out, &err), 2);
  EXPECT_EQ(kinema("demo ccd-steps --out " + dir + " --size 10x10", &out, &err), 1);
  EXPECT_EQ(kinema("demo ccd-steps", &out, &err), 2);  // no --out
}

TEST(DemoCommand, WritesStepsPlotNumbersAndACaseThatKinemaIkReplays) {
  const std::string dir = test::makeTempDir();
  std::string out, err;
  ASSERT_EQ(kinema("demo ccd-steps --out " + dir + " --size 640x480", &out, &err), 0) << err;
  EXPECT_NE(err.find("ccd"), std::string::npos);  // progress on stderr
  for (const char* f : {"convergence.png", "numbers.json", "numbers.csv", "case.kinema", "commands.txt", "ccd/step_000.png",
                        "fabrik/step_000.png"})
    EXPECT_TRUE(fs::exists(fs::path(dir) / f)) << f;
  const Json numbers = Json::parse(test::readFile(dir + "/numbers.json"));
  ASSERT_EQ(numbers["solvers"].size(), 2u);
  for (const Json& s : numbers["solvers"]) {
    const int entries = static_cast<int>(s["trace"].size());
    // One image per trace entry, numbered by entry.
    for (int k = 0; k < entries; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "step_%03d.png", k);
      EXPECT_TRUE(fs::exists(fs::path(dir) / s["solver"].get<std::string>() / name)) << name;
    }
    // The recorded command, run by the real binary in that folder, prints the same trace.
    std::string command = s["command"].get<std::string>();
    ASSERT_EQ(command.rfind("kinema ik ", 0), 0u) << command;
    std::string replay;
    ASSERT_EQ(test::runCommand("cd " + dir + " && " + std::string(KINEMA_BINARY) + command.substr(6), &replay, &err), 0)
        << command << "\n" << err;
    const Json ik = Json::parse(replay);
    EXPECT_EQ(ik["trace"], s["trace"]) << s["solver"];
    EXPECT_EQ(ik["trace_joints"], s["trace_joints"]);
    EXPECT_EQ(ik["iterations"], s["iterations"]);
    EXPECT_EQ(ik["error"], s["error"]);
  }
  // numbers.csv: one row per trace entry plus a total per solver, and the header.
  const std::string csv = test::readFile(dir + "/numbers.csv");
  const size_t rows = std::count(csv.begin(), csv.end(), '\n');
  EXPECT_EQ(rows, 1 + numbers["solvers"][0]["trace"].size() + numbers["solvers"][1]["trace"].size() + 2);

  // Golden pixels: the CLI's first CCD turn, where the figure's mapping puts the chain.
  SolverComparison cmp;
  ASSERT_EQ(startComparison(*findTeachingPreset("ccd-steps"), cmp, 1), "");
  cmp.runs[0].cursor = 1;
  const Figure f = drawSolverStep(cmp, 0, FigureStyle{});
  Result<Image> png = loadPng(dir + "/ccd/step_001.png");
  ASSERT_TRUE(png) << png.error();
  ASSERT_EQ(png->width, 640);
  ASSERT_EQ(png->height, 480);
  const Json& entry = numbers["solvers"][0]["trace"][1];
  for (int b = 0; b < 3; ++b) {
    const glm::vec2 mid(0.5f * (entry["positions"][b][0].get<float>() + entry["positions"][b + 1][0].get<float>()),
                        0.5f * (entry["positions"][b][1].get<float>() + entry["positions"][b + 1][1].get<float>()));
    const glm::vec2 p = figureToPixel(f, 640, 480, mid);
    const std::uint8_t* px = png->pixel(static_cast<int>(p.x), static_cast<int>(p.y));
    const Rgba ccd = solverColor(IkSolver::Ccd);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(px[i], ccd[i], 40) << "bone " << b;
  }
  const glm::vec2 t = figureToPixel(f, 640, 480, {numbers["target"][0].get<float>(), numbers["target"][1].get<float>()});
  const std::uint8_t* tp = png->pixel(static_cast<int>(t.x), static_cast<int>(t.y));
  EXPECT_GT(tp[0], 180);
  EXPECT_LT(tp[1], 110);
}

TEST(DemoCommand, SolverTableWritesEveryFormat) {
  const std::string dir = test::makeTempDir();
  std::string out, err;
  ASSERT_EQ(kinema("demo solver-table --out " + dir + " --targets 3", &out, &err), 0) << err;
  const Json table = Json::parse(test::readFile(dir + "/solver_table.json"));
  ASSERT_EQ(table["rows"].size(), 10u);  // 5 solvers x (reachable, unreachable)
  for (const Json& r : table["rows"]) {
    EXPECT_EQ(r["count"], 3);
    if (r["targets"] == "unreachable") {
      EXPECT_EQ(r["converged"], 0) << r["solver"];
    }
  }
  for (const char* f : {"solver_table.md", "solver_table.csv", "solver_table.png"})
    EXPECT_TRUE(fs::exists(fs::path(dir) / f)) << f;
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

// ffmpeg is optional: with one on PATH (here a stand-in that records its arguments and
// writes its output file) each solver gets a GIF and an MP4 made from its step images.
TEST(DemoCommand, MakesGifAndMp4WithFfmpegOnPath) {
  const std::string dir = test::makeTempDir(), bin = test::makeTempDir();
  test::writeFile(bin + "/ffmpeg",
                  "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done >> \"" + bin +
                      "/args.txt\"\nfor a in \"$@\"; do last=$a; done\n: > \"$last\"\n");
  ASSERT_EQ(test::runCommand("chmod +x " + bin + "/ffmpeg"), 0);
  std::string out, err;
  ASSERT_EQ(test::runCommand("PATH=" + bin + ":$PATH " + std::string(KINEMA_BINARY) + " demo fabrik-steps --out " + dir,
                             &out, &err),
            0)
      << err;
  for (const char* f : {"fabrik.gif", "fabrik.mp4", "ccd.gif", "ccd.mp4"})
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / f)) << f;
  const std::string args = test::readFile(bin + "/args.txt");
  // The frame pattern reaches ffmpeg as one argument, unexpanded by the shell.
  EXPECT_NE(args.find("\n" + dir + "/fabrik/step_*.png\n"), std::string::npos) << args;
  EXPECT_EQ(err.find("not on PATH"), std::string::npos) << err;
}

// Without ffmpeg the demo still writes everything else and says, in one line, why there is
// no GIF or MP4.
TEST(DemoCommand, SaysSoWhenFfmpegIsAbsent) {
  const std::string dir = test::makeTempDir(), empty = test::makeTempDir();
  std::string out, err;
  ASSERT_EQ(test::runCommand("PATH=" + empty + " " + std::string(KINEMA_BINARY) + " demo ccd-steps --out " + dir, &out, &err),
            0)
      << err;
  EXPECT_NE(err.find("ffmpeg is not on PATH"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(dir) / "ccd.gif"));
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / "ccd" / "step_000.png"));
}

// With the real ffmpeg (.ci installs it), the GIF's frames keep the figure's colours: its
// first frame, decoded again by ffmpeg, matches step_000.png on the drawn (non-white) pixels.
// ffmpeg's default GIF palette for RGBA frames once turned black and grey into yellow.
TEST(DemoCommand, TheGifKeepsTheFiguresColours) {
  if (test::runCommand("command -v ffmpeg >/dev/null 2>&1 && ffmpeg -version | grep -q '^ffmpeg version'") != 0)
    GTEST_SKIP() << "ffmpeg is not installed (optional Debian package): no GIF to check";
  const std::string dir = test::makeTempDir();
  std::string out, err;
  ASSERT_EQ(test::runCommand(std::string(KINEMA_BINARY) + " demo ccd-steps --out " + dir, &out, &err), 0) << err;
  ASSERT_EQ(test::runCommand("ffmpeg -v error -y -i " + dir + "/ccd.gif -vframes 1 " + dir + "/gif_frame0.png", &out, &err), 0)
      << err;
  const Result<Image> png = loadPng(dir + "/ccd/step_000.png"), gif = loadPng(dir + "/gif_frame0.png");
  ASSERT_TRUE(png.ok()) << png.error();
  ASSERT_TRUE(gif.ok()) << gif.error();
  ASSERT_EQ(png.value().width, gif.value().width);
  ASSERT_EQ(png.value().height, gif.value().height);
  double sum = 0.0;
  long drawn = 0;
  for (int y = 0; y < png.value().height; ++y)
    for (int x = 0; x < png.value().width; ++x) {
      const std::uint8_t* a = png.value().pixel(x, y);
      const std::uint8_t* b = gif.value().pixel(x, y);
      if (a[0] > 245 && a[1] > 245 && a[2] > 245) continue;  // background
      ++drawn;
      for (int c = 0; c < 3; ++c) sum += std::abs(int(a[c]) - int(b[c]));
    }
  ASSERT_GT(drawn, 1000);
  EXPECT_LT(sum / (3.0 * drawn), 12.0) << "mean difference per channel on " << drawn << " drawn pixels";
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

// Issue 23: `kinema demo stiff-springs`. The limits in numbers.json against the closed forms
// computed here from the chain's parameters (w_max of a fixed-free chain of N masses), and the
// measured blow-up steps within 5 % above them.
TEST(DemoCommand, StiffSpringsWritesTheFiguresAndLimits) {
  const std::string dir = test::makeTempDir();
  std::string out, err;
  ASSERT_EQ(kinema("demo stiff-springs --out " + dir + " --size 800x480 --zeta 0.2", &out, &err), 0) << err;
  const Json n = Json::parse(test::readFile(dir + "/numbers.json"));
  const double pi = 3.14159265358979323846, masses = n["masses"].get<double>();
  const double wMax = 2.0 * std::sqrt(n["stiffness_n_per_m"].get<double>() / n["mass_kg"].get<double>()) *
                      std::sin((2.0 * masses - 1.0) * pi / (2.0 * (2.0 * masses + 1.0)));
  EXPECT_NEAR(n["omega_max_rad_per_s"].get<double>(), wMax, 1e-9 * wMax);
  const double zeta = 0.2;
  ASSERT_EQ(n["limits"].size(), 4u);
  EXPECT_EQ(n["limits"][0]["scheme"], "explicit_euler");
  EXPECT_NEAR(n["limits"][0]["derived_limit_s"].get<double>(), 2.0 * zeta / wMax, 1e-12);
  EXPECT_EQ(n["limits"][1]["scheme"], "symplectic_euler");
  EXPECT_NEAR(n["limits"][1]["derived_limit_s"].get<double>(), 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / wMax, 1e-12);
  EXPECT_TRUE(n["limits"][3]["derived_limit_s"].is_null());  // backward Euler
  for (int s = 0; s < 3; ++s) {
    const double derived = n["limits"][s]["derived_limit_s"], measured = n["limits"][s]["measured_blow_up_step_s"];
    EXPECT_GE(measured, derived) << n["limits"][s]["scheme"];
    EXPECT_LE(measured, 1.05 * derived) << n["limits"][s]["scheme"];
  }
  // 4 schemes x 5 steps; backward Euler never blows up, explicit Euler does from the 2nd column.
  ASSERT_EQ(n["runs"].size(), 20u);
  for (int c = 0; c < 5; ++c) {
    EXPECT_FALSE(n["runs"][15 + c]["blew_up"].get<bool>()) << c;
    EXPECT_EQ(n["runs"][c]["blew_up"].get<bool>(), c > 0) << c;
  }
  for (const char* f : {"motion.png", "energy.png", "numbers.csv"}) EXPECT_TRUE(fs::exists(fs::path(dir) / f)) << f;
  const Result<Image> img = loadPng(dir + "/energy.png");
  ASSERT_TRUE(img.ok()) << img.error();
  EXPECT_EQ(img->width, 800);  // 5 x 4 panels of 160 x 120
  EXPECT_EQ(img->height, 480);
  EXPECT_EQ(kinema("demo stiff-springs --out " + dir + " --zeta 1.5", &out, &err), 1);
  EXPECT_NE(err.find("zeta"), std::string::npos) << err;
}

}  // namespace
}  // namespace kinema
