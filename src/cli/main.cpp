// kinema: the command-line front end (contract in docs/cli.md).
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/command_line.h"
#include "cli/pose_command.h"
#include "cli/render_command.h"
#include "core/default_character.h"
#include "core/forward_kinematics.h"

namespace {

// Until the editor exists, plain `kinema` describes the default character.
int describeDefaultCharacter() {
  const kinema::Skeleton s = kinema::makeDefaultCharacter();
  const std::vector<glm::mat4> world = kinema::computeWorld(s, kinema::Pose::rest(s));
  float top = 0.0f;
  for (const glm::mat4& m : world) top = std::max(top, m[3].y);
  std::printf("Kinema default character: %d joints, %.2f units tall, T-pose, Y up, facing +Z\n", s.size(), top);
  std::printf("%4s  %-14s %-14s %9s %9s %9s\n", "#", "joint", "parent", "x", "y", "z");
  for (int i = 0; i < s.size(); ++i)
    std::printf("%4d  %-14s %-14s %9.3f %9.3f %9.3f\n", i, s.names[i].c_str(),
                s.parents[i] < 0 ? "-" : s.names[s.parents[i]].c_str(), world[i][3].x, world[i][3].y,
                world[i][3].z);
  std::printf("\nTry: kinema pose FILE.bvh --frame 0 --json   (kinema --help lists every subcommand)\n");
  return kinema::cli::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Kinema: skeleton posing, inverse kinematics and keyframe animation", "kinema"};
  app.set_version_flag("--version", "kinema 0.1.0");
  app.require_subcommand(0, 1);
  app.fallthrough(false);

  kinema::cli::PoseOptions pose;
  CLI::App* poseCmd = kinema::cli::addPoseCommand(app, pose);
  kinema::cli::RenderOptions render;
  CLI::App* renderCmd = kinema::cli::addRenderCommand(app, render);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "kinema: " << e.what() << "; see --help\n";
    return kinema::cli::kExitUsage;
  }

  if (poseCmd->parsed()) return kinema::cli::runPose(pose);
  if (renderCmd->parsed()) return kinema::cli::runRender(render);
  return describeDefaultCharacter();
}
