#pragma once
#include <optional>
#include <string>

namespace kinema {

// Which solver drives a chain. Apart from ik_solver.h so that saved rigs (ik_rig.h) can
// name a solver without pulling in the solvers.
enum class IkSolver { TwoBone, Ccd, Fabrik, JacobianTranspose, JacobianPinv, JacobianDls, JacobianSdls };
const char* toString(IkSolver solver);  // "two-bone", "ccd", "fabrik", "jacobian-dls", ...
std::optional<IkSolver> ikSolverFromString(const std::string& name);

// How the editor drives a saved IK target (stored with the rig in .kinema files).
struct IkTargetOptions {
  IkSolver solver = IkSolver::JacobianDls;
  // > 0: the chain is this many bones up from the effector (Blender's chain length) and
  // decides the IK root; 0: the target's root does.
  int chainLength = 0;
  bool pinned = false;  // holds its effector while other targets or joints move
  bool active = true;   // solved at all
};

}  // namespace kinema
