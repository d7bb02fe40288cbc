// kinema: the command-line front end (contract in docs/cli.md).
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/command_line.h"
#include "cli/convert_command.h"
#include "cli/demo_command.h"
#include "cli/edit_command.h"
#include "cli/ik_command.h"
#include "cli/lsystem_command.h"
#include "cli/plot_curves_command.h"
#include "cli/pose_command.h"
#include "cli/render_command.h"
#include "cli/retarget_command.h"
#include "cli/simulate_command.h"
#include "cli/skin_command.h"

int main(int argc, char** argv) {
  CLI::App app{"Kinema: skeleton posing, inverse kinematics and keyframe animation", "kinema"};
  app.set_version_flag("--version", "kinema 0.1.0");
  app.require_subcommand(0, 1);
  app.fallthrough(false);

  kinema::cli::PoseOptions pose;
  CLI::App* poseCmd = kinema::cli::addPoseCommand(app, pose);
  kinema::cli::IkOptions ik;
  CLI::App* ikCmd = kinema::cli::addIkCommand(app, ik);
  kinema::cli::PlotCurvesOptions plotCurves;
  CLI::App* plotCurvesCmd = kinema::cli::addPlotCurvesCommand(app, plotCurves);
  kinema::cli::RenderOptions render;
  CLI::App* renderCmd = kinema::cli::addRenderCommand(app, render);
  kinema::cli::EditOptions edit;
  CLI::App* editCmd = kinema::cli::addEditCommand(app, edit);
  kinema::cli::ConvertOptions convert;
  CLI::App* convertCmd = kinema::cli::addConvertCommand(app, convert);
  kinema::cli::SkinOptions skin;
  CLI::App* skinCmd = kinema::cli::addSkinCommand(app, skin);
  kinema::cli::DemoOptions demo;
  CLI::App* demoCmd = kinema::cli::addDemoCommand(app, demo);
  kinema::cli::RetargetOptions retarget;
  CLI::App* retargetCmd = kinema::cli::addRetargetCommand(app, retarget);
  kinema::cli::LSystemOptions lsystem;
  CLI::App* lsystemCmd = kinema::cli::addLSystemCommand(app, lsystem);
  kinema::cli::SimulateOptions simulate;
  CLI::App* simulateCmd = kinema::cli::addSimulateCommand(app, simulate);

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
  if (ikCmd->parsed()) return kinema::cli::runIk(ik);
  if (plotCurvesCmd->parsed()) return kinema::cli::runPlotCurves(plotCurves);
  if (renderCmd->parsed()) return kinema::cli::runRender(render);
  if (editCmd->parsed()) return kinema::cli::runEdit(edit);
  if (convertCmd->parsed()) return kinema::cli::runConvert(convert);
  if (skinCmd->parsed()) return kinema::cli::runSkin(skin);
  if (demoCmd->parsed()) return kinema::cli::runDemo(demo);
  if (retargetCmd->parsed()) return kinema::cli::runRetarget(retarget);
  if (lsystemCmd->parsed()) return kinema::cli::runLSystem(lsystem);
  if (simulateCmd->parsed()) return kinema::cli::runSimulate(simulate);
  return kinema::cli::runDefault();
}
