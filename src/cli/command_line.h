#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/result.h"
#include "io/scene_files.h"

namespace CLI {
class App;
}

namespace kinema::cli {

// Exit codes of the command-line contract (docs/cli.md).
constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;  // missing or unreadable file, parse error, unknown joint, non-finite number
constexpr int kExitUsage = 2;     // unknown flag or subcommand, malformed argument syntax

// Prints "kinema: MESSAGE" on stderr as one line and returns kExitBadInput.
int badInput(const std::string& message);
// Prints "kinema SUBCOMMAND: MESSAGE; see --help" on stderr and returns kExitUsage.
int usageError(const std::string& subcommand, const std::string& message);

// A file, or the default character when `path` is empty; .bvh files read as `bvhUp`-up.
Result<Scene> loadSceneOrDefault(const std::string& path, const InputLimits& limits = {},
                                 UpAxis bvhUp = UpAxis::Y);

// `--up y|z` on a command that reads files: which axis is up in a BVH file (default y, the
// BVH convention; z for Blender's exports). Other formats are Y-up and ignore it.
CLI::Option* addUpOption(CLI::App* cmd, std::string& up);
UpAxis upAxisOf(const std::string& up);  // "y" or "z" (the option checks it)

// --allow-outside-paths, on every command that reads glTF: buffer and image uris may name
// files outside the glTF file's folder (never devices, FIFOs, sockets or /proc).
void addAllowOutsidePathsFlag(CLI::App* cmd, bool& allowOutsidePaths);
// The default input limits with the flag applied.
InputLimits inputLimits(bool allowOutsidePaths);


// Empty when `clip` names one of the scene's clips (0 is always allowed: a file without
// clips evaluates to its rest pose); otherwise the one-line error.
std::string clipIndexError(const Scene& scene, int clip);

// --reduce POS[,DEG] of `retarget` and `simulate`: two numbers (ranges are checked as bad
// input), DEG kDefaultReduceDegrees when left out. False when the text is not that.
constexpr double kDefaultReduceDegrees = 0.5;
bool parseReduce(const std::string& text, double& pos, double& deg);

// The time the subcommands evaluate for --time T: T, clamped to the clip's keys when the clip
// has channel modifiers (they act past the last key; the contract clamps).
double contractTime(const Scene& scene, int clip, double time);
// The local pose at `time` in clip `clip` through the evaluation pipeline (every stage:
// evaluation/scene_evaluation_job.h), or the rest pose when the file has no clips.
Pose sampledPose(const Scene& scene, int clip, double time);

// The "joints" array of the contract: name, parent, world (16 numbers, column-major).
nlohmann::ordered_json jointsJson(const Skeleton& skeleton, const std::vector<glm::mat4>& world);
// The same for a scene: glTF scenes list one entry per node in node-index order, with
// "node", the file's name and the parent's node index; other scenes as above.
nlohmann::ordered_json jointsJson(const Scene& scene, const std::vector<glm::mat4>& world);

}  // namespace kinema::cli
