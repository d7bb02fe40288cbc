#pragma once
#include <string>

namespace kinema::cli {

// `kinema demo stiff-springs --out DIR [--zeta Z] [--size WxH]`: the damped spring chain run
// by explicit Euler, symplectic Euler, Verlet and backward Euler at growing time steps
// (sim/stability_sweep.h): motion.png (the tip's displacement), energy.png (log10 of the
// energy over its start), numbers.json and numbers.csv (derived and measured limits, every run).
// panelWidth x panelHeight: one panel's size in pixels (5 columns x 4 rows of panels).
int runStiffSpringsDemo(const std::string& out, double zeta, int panelWidth, int panelHeight);

}  // namespace kinema::cli
