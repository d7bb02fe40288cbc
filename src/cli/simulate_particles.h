#pragma once
// `kinema simulate`'s particle systems and --render (issue 24): the options, the report and
// the frames, kept apart from simulate_command.cpp, which bakes chains and ragdolls.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/simulate_command.h"
#include "scene/scene.h"

namespace kinema::cli {

// --render DIR, --size WxH, --camera AZ,EL[,DIST], --backend egl|osmesa.
void addSimulateRenderOptions(CLI::App* cmd, SimulateOptions& options);
// False (after one line on stderr) when --size or --camera is malformed: checked before any
// simulation runs.
bool simulateRenderSyntaxOk(const SimulateOptions& options);
// The frames a particles-only file plays without --frames: the clip's, or 0..119 (four
// seconds at 30 fps) for a file without clips or with a one-frame clip.
void defaultParticleFrames(const Scene& scene, int clip, long long& first, long long& last);
// The report's parts for the particle systems, played from frame 0 to `last`: {"kind":
// "particles", "name", "frames": [first, last], "steps" (frames stepped from 0), "alive" and
// "emitted" (born so far) at `last`}.
nlohmann::ordered_json particleReport(const Scene& scene, int clip, long long first, long long last);
// With --render: frames first..last of `scene` as DIR/frame_NNNN.png (kinema render's code).
int renderSimulatedFrames(const SimulateOptions& options, const Scene& scene, long long first, long long last);
// A file whose simulation is particles alone: nothing to bake; --out writes it as it is.
int runParticlesOnly(const SimulateOptions& options, const Scene& scene, long long first, long long last);

}  // namespace kinema::cli
