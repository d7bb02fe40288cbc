#include "cli/demo_command.h"

#include "cli/ik_trace_json.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "cli/boids_demo.h"
#include "cli/life_demo.h"
#include "cli/stiff_springs_demo.h"
#include "ik/solver_comparison.h"
#include "ik/solver_table.h"
#include "io/atomic_write.h"
#include "io/json_number.h"
#include "io/kinema_file.h"
#include "render/solver_figure.h"

namespace kinema::cli {

namespace {

namespace fs = std::filesystem;

std::string presetNames() {
  std::string names;
  for (const TeachingCase& c : teachingPresets()) names += (names.empty() ? "" : ", ") + c.name;
  return names;
}

// For /bin/sh: left bare only when every character is harmless there.
std::string quoted(const std::string& s) {
  const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("-_./,=:+@%", c) != nullptr;
  });
  if (plain) return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream ss(path);
  std::string dir;
  std::error_code ec;
  while (std::getline(ss, dir, ':'))
    if (!dir.empty() && fs::exists(fs::path(dir) / program, ec)) return true;
  return false;
}


std::string ikCommand(const TeachingCase& setup, IkSolver solver, const std::string& file) {
  std::string cmd = "kinema ik " + quoted(file);
  for (const std::string& a : ikCommandArguments(setup, solver)) cmd += " " + quoted(a);
  return cmd + " --json --trace";
}

std::string writeText(const fs::path& path, const std::string& text) { return writeFileAtomically(path.string(), text); }

int runPreset(const TeachingCase& preset, const DemoOptions& o, int width, int height) {
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) return badInput(o.out + ": cannot create the folder (" + ec.message() + ")");
  SolverComparison cmp;
  if (const std::string bad = startComparison(preset, cmp); !bad.empty()) return badInput(bad);
  FigureStyle style;
  const fs::path out(o.out);

  // The case itself, so `kinema ik case.kinema ... --trace` replays every solver.
  Scene scene;
  scene.source = (out / "case.kinema").string();
  scene.skeleton = cmp.chain.skeleton;
  scene.ik = cmp.chain.rig;
  if (std::string bad = saveKinemaFile((out / "case.kinema").string(), scene); !bad.empty()) return badInput(bad);

  nlohmann::ordered_json numbers;
  numbers["preset"] = preset.name;
  numbers["title"] = preset.title;
  numbers["description"] = preset.description;
  numbers["target"] = {jsonFloat(cmp.setup.target.x), jsonFloat(cmp.setup.target.y), jsonFloat(cmp.setup.target.z)};
  numbers["reach"] = jsonFloat(cmp.setup.chain.reach());
  numbers["tolerance"] = jsonFloat(cmp.setup.settings.tolerance);
  nlohmann::ordered_json solvers = nlohmann::ordered_json::array();
  std::string csv = "solver,entry,iteration,step,joint,error,ms_total,ms_per_iteration\n";
  std::string commands = "# Each line replays one solver's trace of this case (run in this folder).\n";
  char buf[160];
  for (size_t r = 0; r < cmp.runs.size(); ++r) {
    SolverRun& run = cmp.runs[r];
    const std::string name = toString(run.solver);
    const fs::path dir = out / name;
    fs::create_directories(dir, ec);
    if (ec) return badInput(dir.string() + ": cannot create the folder (" + ec.message() + ")");
    const int entries = static_cast<int>(run.trace.entries.size());
    int written = 0;
    for (int k = 0; k < entries; ++k) {
      if (o.maxSteps > 0 && k >= o.maxSteps && k != entries - 1) continue;
      run.cursor = k;
      const Image img = rasterizeFigure(drawSolverStep(cmp, static_cast<int>(r), style), width, height, true);
      std::snprintf(buf, sizeof buf, "step_%03d.png", k);
      if (std::string bad = savePng((dir / buf).string(), img); !bad.empty()) return badInput(bad);
      ++written;
    }
    run.cursor = 0;
    std::cerr << "kinema demo: " << preset.name << ": " << name << ": " << written << " of " << entries
              << " steps drawn in " << dir.string() << "\n";
    if (onPath("ffmpeg")) {
      for (const char* ext : {"gif", "mp4"}) {
        const std::string movie = (out / (name + "." + ext)).string();
        const std::string cmd = "ffmpeg -y -loglevel error -framerate 2 -pattern_type glob -i " +
                                quoted((dir / "step_*.png").string()) +
                                // GIF: a palette made from the frames themselves (ffmpeg's default
                                // palette for RGBA input turns greys and black into yellow).
                                (std::string(ext) == "mp4"
                                     ? " -pix_fmt yuv420p -vf " + quoted("scale=trunc(iw/2)*2:trunc(ih/2)*2") + " "
                                     : " -vf " + quoted("split[a][b];[a]palettegen=reserve_transparent=0[p];[b][p]paletteuse") + " ") +
                                quoted(movie);
        if (std::system(cmd.c_str()) != 0) std::cerr << "kinema demo: ffmpeg failed to write " << movie << "\n";
      }
    }
    nlohmann::ordered_json s;
    s["solver"] = name;
    s["converged"] = run.result.converged;
    s["iterations"] = run.result.iterations;
    s["error"] = jsonFloat(run.result.error);
    s["ms_total"] = run.totalMilliseconds;
    s["ms_per_iteration"] = run.millisecondsPerIteration;
    s["command"] = ikCommand(cmp.setup, run.solver, "case.kinema");
    nlohmann::ordered_json joints = nlohmann::ordered_json::array();
    for (int j : run.trace.joints) joints.push_back(j);
    s["trace_joints"] = std::move(joints);
    s["trace"] = ikTraceJson(run.trace);
    solvers.push_back(std::move(s));
    for (int k = 0; k < entries; ++k) {
      const IkTraceEntry& e = run.trace.entries[k];
      std::snprintf(buf, sizeof buf, "%s,%d,%d,%s,%s,%.9g,,\n", name.c_str(), k, e.iteration, toString(e.step),
                    e.joint >= 0 ? std::to_string(e.joint).c_str() : "", static_cast<double>(e.error));
      csv += buf;
    }
    std::snprintf(buf, sizeof buf, "%s,,%d,total,,%.9g,%.6f,%.6f\n", name.c_str(), run.result.iterations,
                  static_cast<double>(run.result.error), run.totalMilliseconds, run.millisecondsPerIteration);
    csv += buf;
    commands += ikCommand(cmp.setup, run.solver, "case.kinema") + "\n";
  }
  if (!onPath("ffmpeg")) std::cerr << "kinema demo: ffmpeg is not on PATH (apt-get install ffmpeg): no GIF or MP4 written\n";
  numbers["solvers"] = std::move(solvers);
  runToEnd(cmp);  // the plot of the whole runs
  const Image plot = rasterizeFigure(drawConvergencePlot(cmp, style), width, static_cast<int>(width / 1.6f), true);
  if (std::string bad = savePng((out / "convergence.png").string(), plot); !bad.empty()) return badInput(bad);
  for (const auto& [file, text] : {std::pair<const char*, std::string>{"numbers.json", numbers.dump() + "\n"},
                                   {"numbers.csv", csv}, {"commands.txt", commands}})
    if (std::string bad = writeText(out / file, text); !bad.empty()) return badInput(bad);
  std::printf("wrote %s: %zu solvers, convergence.png, numbers.json, numbers.csv, case.kinema, commands.txt\n",
              o.out.c_str(), cmp.runs.size());
  return kExitOk;
}

// Two panels of grouped bars (reachable, unreachable per solver), log scale: mean
// iterations and mean milliseconds per solve.
Figure solverTableChart(const std::vector<SolverTableRow>& rows, const SolverTableOptions& opt) {
  Figure f;
  f.min = {0.0f, 0.0f};
  f.max = {2.0f, 1.0f};
  const Rgba ink{30, 30, 30, 255}, faint{120, 120, 120, 255}, grid{225, 225, 225, 255};
  for (int panel = 0; panel < 2; ++panel) {
    const float x0 = 0.12f + panel * 1.0f, x1 = x0 + 0.82f, y0 = 0.16f, y1 = 0.84f;
    double lo = 1e30, hi = 0.0;
    for (const SolverTableRow& r : rows) {
      const double v = panel == 0 ? r.meanIterations : r.meanMilliseconds;
      if (v > 0) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (hi <= 0) lo = 0.1, hi = 1;
    // A decade below the smallest bar, so a mean of exactly 1 still shows.
    const int d0 = static_cast<int>(std::floor(std::log10(lo * 0.999))), d1 = std::max(d0 + 1, static_cast<int>(std::ceil(std::log10(hi))));
    auto y = [&](double v) {
      return y0 + (y1 - y0) * static_cast<float>((std::log10(std::max(v, std::pow(10.0, d0))) - d0) / (d1 - d0));
    };
    for (int d = d0; d <= d1; ++d) {
      const float yy = y(std::pow(10.0, d));
      f.lines.push_back({{x0, yy}, {x1, yy}, grid, 1.0f, false});
      f.texts.push_back({{x0 - 0.1f, yy + 0.015f}, "1e" + std::to_string(d), faint, 1});
    }
    f.lines.push_back({{x0, y0}, {x1, y0}, ink, 1.5f, false});
    f.texts.push_back({{x0, 0.95f}, panel == 0 ? "mean iterations (log)" : "mean ms per solve (log)", ink, 2});
    const int n = static_cast<int>(rows.size());
    const float slot = (x1 - x0) / static_cast<float>(std::max(1, n / 2));
    for (int i = 0; i < n; ++i) {
      const SolverTableRow& r = rows[i];
      const double v = panel == 0 ? r.meanIterations : r.meanMilliseconds;
      const float bx = x0 + slot * static_cast<float>(i / 2) + slot * (r.reachable ? 0.12f : 0.5f);
      const float bw = slot * 0.36f;
      Rgba c = solverColor(r.solver);
      if (!r.reachable) c[3] = 110;
      f.polygons.push_back({{{bx, y0}, {bx + bw, y0}, {bx + bw, y(v)}, {bx, y(v)}}, c});
      if (r.reachable) f.texts.push_back({{bx, y0 - 0.02f}, solverDisplayName(r.solver, true), ink, 1});
    }
  }
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%d-bone 3D chain, %d random targets each: solid = reachable, light = unreachable; tolerance %g, cap %d",
                opt.bones, opt.targets, static_cast<double>(opt.tolerance), opt.maxIterations);
  f.texts.push_back({{0.12f, 0.06f}, buf, faint, 1});
  return f;
}

int runSolverTable(const DemoOptions& o, int width, int height) {
  SolverTableOptions opt;
  opt.targets = o.targets;
  opt.seed = o.seed;
  if (const std::string bad = opt.validate(); !bad.empty()) return badInput("solver-table: " + bad);
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) return badInput(o.out + ": cannot create the folder (" + ec.message() + ")");
  std::cerr << "kinema demo: solver-table: " << opt.solvers.size() << " solvers x " << 2 * opt.targets
            << " targets on a " << opt.bones << "-bone chain...\n";
  const std::vector<SolverTableRow> rows = computeSolverTable(opt);
  const fs::path out(o.out);
  std::string md = "| solver | targets | converged | mean iterations | mean ms | ms / iteration | mean error |\n"
                   "|---|---|---|---|---|---|---|\n";
  std::string csv = "solver,targets,reachable,count,converged,mean_iterations,mean_ms,ms_per_iteration,mean_error\n";
  nlohmann::ordered_json json;
  json["bones"] = opt.bones;
  json["targets_per_set"] = opt.targets;
  json["seed"] = opt.seed;
  json["tolerance"] = jsonFloat(opt.tolerance);
  json["max_iterations"] = opt.maxIterations;
  nlohmann::ordered_json jr = nlohmann::ordered_json::array();
  char buf[300];
  for (const SolverTableRow& r : rows) {
    std::snprintf(buf, sizeof buf, "| %s | %s | %d / %d | %.1f | %.4f | %.5f | %.3g |\n", toString(r.solver),
                  r.reachable ? "reachable" : "unreachable", r.converged, r.targets, r.meanIterations, r.meanMilliseconds,
                  r.millisecondsPerIteration, r.meanError);
    md += buf;
    std::snprintf(buf, sizeof buf, "%s,%s,%d,%d,%.3f,%.6f,%.6f,%.6g\n", toString(r.solver),
                  r.reachable ? "reachable" : "unreachable", r.targets, r.converged, r.meanIterations, r.meanMilliseconds,
                  r.millisecondsPerIteration, r.meanError);
    csv += buf;
    nlohmann::ordered_json j;
    j["solver"] = toString(r.solver);
    j["targets"] = r.reachable ? "reachable" : "unreachable";
    j["count"] = r.targets;
    j["converged"] = r.converged;
    j["mean_iterations"] = r.meanIterations;
    j["mean_ms"] = r.meanMilliseconds;
    j["ms_per_iteration"] = r.millisecondsPerIteration;
    j["mean_error"] = r.meanError;
    jr.push_back(std::move(j));
  }
  json["rows"] = std::move(jr);
  for (const auto& [file, text] : {std::pair<const char*, std::string>{"solver_table.md", md},
                                   {"solver_table.csv", csv}, {"solver_table.json", json.dump(2) + "\n"}})
    if (std::string bad = writeText(out / file, text); !bad.empty()) return badInput(bad);
  const Image chart = rasterizeFigure(solverTableChart(rows, opt), width, std::max(1, width / 2), true);
  if (std::string bad = savePng((out / "solver_table.png").string(), chart); !bad.empty()) return badInput(bad);
  (void)height;
  std::printf("%s", md.c_str());
  std::printf("wrote %s: solver_table.md, solver_table.csv, solver_table.json, solver_table.png\n", o.out.c_str());
  return kExitOk;
}

}  // namespace

CLI::App* addDemoCommand(CLI::App& app, DemoOptions& o) {
  CLI::App* cmd = app.add_subcommand("demo", "Teaching figures: every solver step of a preset as PNG, plots and numbers");
  cmd->add_option("name", o.name, "A preset (see `kinema demo list`), list, solver-table, stiff-springs, life or boids")->required();
  cmd->add_option("--out", o.out, "Output folder (created)");
  cmd->add_option("--size", o.size, "Image size WxH in pixels (default 640x480)");
  cmd->add_option("--max-steps", o.maxSteps, "At most N step images per solver, plus the last (default: all)");
  cmd->add_option("--targets", o.targets, "solver-table: random targets per set (default 100)");
  cmd->add_option("--seed", o.seed, "solver-table: random seed (default 1)");
  cmd->add_option("--zeta", o.zeta, "stiff-springs: damping ratio of the chain's highest mode, in (0, 1] (default 0.3)");
  cmd->add_flag("--json", o.json, "list: print JSON");
  return cmd;
}

int runDemo(const DemoOptions& o) {
  if (o.name == "list") {
    // Figure demos draw teaching figures but are not IK cases: `kinema edit --compare` takes
    // only the presets, so the JSON says which is which (`kind`).
    struct FigureDemo {
      const char* name;
      const char* title;
    };
    static const FigureDemo kFigureDemos[] = {
        {"solver-table", "The FABRIK paper's comparison of every solver (kinema demo solver-table --out DIR)"},
        {"stiff-springs", "Why a time step blows up: four integrators on a damped spring chain (kinema demo stiff-springs --out DIR)"},
        {"boids", "Priority acceleration allocation vs the naive average: a flock past obstacles (kinema demo boids --out DIR)"},
        {"life", "Conway's Game of Life, the seed's rules: a glider gun and still lifes (kinema demo life --out DIR)"},
    };
    if (o.json) {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const TeachingCase& c : teachingPresets()) {
        nlohmann::ordered_json j;
        j["name"] = c.name;
        j["kind"] = "ik-preset";
        j["title"] = c.title;
        j["description"] = c.description;
        nlohmann::ordered_json s = nlohmann::ordered_json::array();
        for (IkSolver v : c.solvers) s.push_back(toString(v));
        j["solvers"] = std::move(s);
        list.push_back(std::move(j));
      }
      for (const FigureDemo& d : kFigureDemos) {
        nlohmann::ordered_json j;
        j["name"] = d.name;
        j["kind"] = "figure";
        j["title"] = d.title;
        list.push_back(std::move(j));
      }
      std::cout << list.dump(-1) << "\n";
    } else {
      for (const TeachingCase& c : teachingPresets()) std::printf("%-24s %s\n", c.name.c_str(), c.title.c_str());
      for (const FigureDemo& d : kFigureDemos) std::printf("%-24s %s\n", d.name, d.title);
    }
    return kExitOk;
  }
  int w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(o.size.c_str(), "%dx%d%c", &w, &h, &tail) != 2) return usageError("demo", "--size '" + o.size + "' is not WxH");
  if (w < 160 || h < 120 || w > 4000 || h > 4000)
    return badInput("--size: expected 160 <= W <= 4000 and 120 <= H <= 4000, found '" + o.size + "'");
  if (o.maxSteps < 0) return badInput("--max-steps must be >= 0");
  if (o.out.empty()) return usageError("demo", "give --out DIR");
  if (o.name == "solver-table") return runSolverTable(o, w, h);
  if (o.name == "life") return runLifeDemo(o.out, w, h);
  if (o.name == "boids") return runBoidsDemo(o.out, w, h);
  if (o.name == "stiff-springs") return runStiffSpringsDemo(o.out, o.zeta, std::max(160, w / 5), std::max(120, h / 4));  // 5 x 4 panels
  const TeachingCase* preset = findTeachingPreset(o.name);
  if (!preset)
    return badInput("no demo preset named '" + o.name + "' (presets: " + presetNames() + ", solver-table, stiff-springs, life, boids)");
  return runPreset(*preset, o, w, h);
}

}  // namespace kinema::cli
