#include "cli/stiff_springs_demo.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/command_line.h"
#include "io/atomic_write.h"
#include "io/image.h"
#include "render/curve_plot.h"
#include "sim/stability_sweep.h"

namespace kinema::cli {
namespace {

namespace fs = std::filesystem;

const char* displayName(Integrator i) {
  switch (i) {
    case Integrator::ExplicitEuler: return "explicit Euler";
    case Integrator::SymplecticEuler: return "symplectic Euler";
    case Integrator::Verlet: return "Verlet";
    case Integrator::ImplicitEuler: return "backward Euler";
  }
  return "";
}

Rgb schemeColor(Integrator i) {
  switch (i) {
    case Integrator::ExplicitEuler: return {200, 50, 40};
    case Integrator::SymplecticEuler: return {40, 90, 200};
    case Integrator::Verlet: return {30, 150, 70};
    case Integrator::ImplicitEuler: return {140, 70, 170};
  }
  return {0, 0, 0};
}

std::vector<PlotPanel> panels(const StabilitySweep& sweep, const StabilitySweepOptions& o, bool energy) {
  std::vector<PlotPanel> out;
  char buf[160];
  for (const StabilityRun& run : sweep.runs) {
    PlotPanel p;
    if (run.blewUp)
      std::snprintf(buf, sizeof buf, "%s, h = %.2f ms: blows up at %.2f s", displayName(run.integrator), run.step * 1e3,
                    run.blowUpTime);
    else
      std::snprintf(buf, sizeof buf, "%s, h = %.2f ms: stable", displayName(run.integrator), run.step * 1e3);
    p.title = buf;
    PlotCurve c;
    c.color = schemeColor(run.integrator);
    c.label = energy ? "log10(E / E0)" : "tip / start";
    for (size_t i = 0; i < run.times.size(); ++i) {
      const double y = energy ? std::log10(std::max(run.energyRatio[i], 1e-300)) : run.tip[i] / o.tipDisplacement;
      const double shown = energy ? std::clamp(y, -8.0, 3.0) : std::clamp(y, -1.6, 1.6);
      c.points.emplace_back(static_cast<float>(run.times[i]), static_cast<float>(shown));
    }
    p.curves.push_back(std::move(c));
    if (energy) {  // the blow-up threshold, dashed by sparse points would mislead: a flat line
      PlotCurve t;
      t.color = {150, 150, 150};
      std::snprintf(buf, sizeof buf, "blow-up: %gx", o.blowUpFactor);
      t.label = buf;
      t.points = {{0.0f, static_cast<float>(std::log10(o.blowUpFactor))},
                  {static_cast<float>(o.seconds), static_cast<float>(std::log10(o.blowUpFactor))}};
      p.curves.push_back(std::move(t));
    }
    p.min = {0.0f, energy ? -8.0f : -1.6f};
    p.max = {static_cast<float>(o.seconds), energy ? 3.0f : 1.6f};
    p.legendAtBottom = energy;
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

int runStiffSpringsDemo(const std::string& outDir, double zeta, int panelWidth, int panelHeight) {
  StabilitySweepOptions o;
  o.zeta = zeta;
  if (std::string bad = o.validate(); !bad.empty()) return badInput("stiff-springs: --zeta: " + bad);
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) return badInput(outDir + ": cannot create the folder (" + ec.message() + ")");
  std::cerr << "kinema demo: stiff-springs: " << o.chain.masses << " masses, zeta " << zeta
            << " on the highest mode, 4 schemes x 5 time steps, " << o.seconds << " s each...\n";
  const StabilitySweep sweep = runStabilitySweep(o);
  const fs::path out(outDir);
  const int columns = static_cast<int>(sweep.steps.size());
  for (bool energy : {false, true}) {
    const Image img = plotPanels(panels(sweep, o, energy), columns, panelWidth, panelHeight);
    const std::string file = (out / (energy ? "energy.png" : "motion.png")).string();
    if (std::string bad = savePng(file, img); !bad.empty()) return badInput(bad);
  }
  nlohmann::ordered_json j;
  j["masses"] = sweep.chain.masses;
  j["mass_kg"] = sweep.chain.mass;
  j["stiffness_n_per_m"] = sweep.chain.stiffness;
  j["zeta_highest_mode"] = zeta;
  j["beta_s"] = sweep.chain.beta;
  j["omega_max_rad_per_s"] = sweep.omegaMax;
  j["seconds"] = o.seconds;
  j["blow_up_factor"] = o.blowUpFactor;
  nlohmann::ordered_json limits = nlohmann::ordered_json::array();
  std::string csv = "scheme,step_s,blew_up,blow_up_time_s,final_energy_ratio\n";
  std::printf("| scheme | derived limit (ms) | measured blow-up step (ms) | measured / derived |\n|---|---|---|---|\n");
  for (const SchemeLimits& l : sweep.limits) {
    nlohmann::ordered_json e;
    e["scheme"] = toString(l.integrator);
    if (std::isfinite(l.derived)) {
      e["derived_limit_s"] = l.derived;
      e["measured_blow_up_step_s"] = l.measured;
      std::printf("| %s | %.4f | %.4f | %.3f |\n", displayName(l.integrator), l.derived * 1e3, l.measured * 1e3,
                  l.measured / l.derived);
    } else {
      e["derived_limit_s"] = nullptr;  // unconditionally stable
      std::printf("| %s | none (stable at every step) | none | - |\n", displayName(l.integrator));
    }
    limits.push_back(std::move(e));
  }
  j["limits"] = std::move(limits);
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  char buf[200];
  for (const StabilityRun& r : sweep.runs) {
    nlohmann::ordered_json e;
    e["scheme"] = toString(r.integrator);
    e["step_s"] = r.step;
    e["blew_up"] = r.blewUp;
    if (r.blewUp) e["blow_up_time_s"] = r.blowUpTime;
    e["final_energy_ratio"] = r.energyRatio.back();
    runs.push_back(std::move(e));
    std::snprintf(buf, sizeof buf, "%s,%.9g,%d,%.9g,%.9g\n", toString(r.integrator), r.step, r.blewUp ? 1 : 0,
                  r.blewUp ? r.blowUpTime : 0.0, r.energyRatio.back());
    csv += buf;
  }
  j["runs"] = std::move(runs);
  for (const auto& [file, text] :
       {std::pair<const char*, std::string>{"numbers.json", j.dump(2) + "\n"}, {"numbers.csv", csv}})
    if (std::string bad = writeFileAtomically((out / file).string(), text); !bad.empty()) return badInput(bad);
  std::printf("wrote %s: motion.png, energy.png, numbers.json, numbers.csv\n", outDir.c_str());
  return kExitOk;
}

}  // namespace kinema::cli
