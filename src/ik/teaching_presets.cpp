// The teaching presets (issue 10): the seed's 3-bone CCD and FABRIK figures, its two-bone
// no-solution region and two-solution case, and the cases where the solvers differ most.
// Names are stable: `kinema demo NAME` and the editor's preset menu use them.
#include <cmath>

#include "ik/solver_comparison.h"

namespace kinema {

namespace {

TeachingChain chainOf(std::vector<float> lengths, std::vector<float> angles) {
  TeachingChain c;
  c.boneLengths = std::move(lengths);
  c.startAngles = std::move(angles);
  return c;
}

// The seed's figure (a): three bones, bent up and to the right, the target (red circle)
// above and to the left of the effector.
TeachingChain seedChain() { return chainOf({1.0f, 0.8f, 0.6f}, {0.25f, 0.55f, 0.55f}); }

std::vector<TeachingCase> makePresets() {
  std::vector<TeachingCase> out;
  {
    TeachingCase c;
    c.name = "ccd-steps";
    c.title = "CCD on the seed's 3-bone chain";
    c.description =
        "Each CCD sub-step turns one joint, last joint first, so that the joint, the effector and the "
        "target are collinear; one sweep of three turns is one iteration (seed figure (a)-(d)).";
    c.chain = seedChain();
    c.target = {0.2f, 1.7f, 0.0f};
    c.solvers = {IkSolver::Ccd, IkSolver::Fabrik};
    out.push_back(c);
  }
  {
    TeachingCase c;
    c.name = "fabrik-steps";
    c.title = "FABRIK on the seed's 3-bone chain";
    c.description =
        "The backward pass puts the effector on the target and drags the chain after it (the root leaves "
        "its base); the forward pass puts the root back and lays the bones towards the backward chain.";
    c.chain = seedChain();
    c.target = {0.2f, 1.7f, 0.0f};
    c.solvers = {IkSolver::Fabrik, IkSolver::Ccd};
    out.push_back(c);
  }
  {
    TeachingCase c;
    c.name = "two-bone-unreachable";
    c.title = "Two bones: the target in the no-solution region";
    c.description =
        "With bones of 1 and 0.5 the effector can only reach the ring between |l1-l2| = 0.5 and l1+l2 = 1.5 "
        "from the root; a target inside the inner circle has no solution, and every solver stops at the "
        "nearest point of the ring.";
    c.chain = chainOf({1.0f, 0.5f}, {0.3f, 1.2f});
    c.target = {0.25f, 0.1f, 0.0f};
    c.solvers = {IkSolver::TwoBone, IkSolver::Ccd, IkSolver::Fabrik};
    out.push_back(c);
  }
  {
    TeachingCase c;
    c.name = "two-bone-two-solutions";
    c.title = "Two bones: two elbow solutions";
    c.description =
        "Inside the ring the target is reached with the elbow on either side of the root-target line "
        "(both drawn); the analytic solver keeps the side the chain starts on, the iterative ones end "
        "where their steps lead.";
    c.chain = chainOf({1.0f, 0.8f}, {0.2f, 0.9f});
    c.target = {1.1f, 0.6f, 0.0f};
    c.solvers = {IkSolver::TwoBone, IkSolver::Ccd, IkSolver::Fabrik};
    out.push_back(c);
  }
  {
    TeachingCase c;
    c.name = "unreachable";
    c.title = "A target out of reach";
    c.description =
        "The target lies beyond the sum of the bone lengths: FABRIK sees it at once and straightens the "
        "chain towards it in one step; CCD and DLS creep towards the straight chain until they stall.";
    c.chain = seedChain();
    c.target = {2.6f, 2.3f, 0.0f};
    c.solvers = {IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianDls};
    out.push_back(c);
  }
  {
    TeachingCase c;
    c.name = "near-root";
    c.title = "A target near the root";
    c.description =
        "The chain must fold back towards its own root: FABRIK's passes alternate between a chain hanging "
        "from the target and one pinned to the base and need more iterations here than CCD's sweeps.";
    c.chain = chainOf({0.7f, 0.6f, 0.5f, 0.4f}, {0.3f, 0.3f, 0.3f, 0.3f});
    c.target = {0.3f, 0.1f, 0.0f};
    c.solvers = {IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianDls};
    out.push_back(c);
  }
  {
    TeachingCase c;
    c.name = "long-chain";
    c.title = "A 20-joint chain";
    c.description =
        "Twenty bones of 0.1: CCD bends the joints near the effector most (a curl at the tip), FABRIK "
        "spreads the bend along the chain and converges in a few passes.";
    c.chain = chainOf(std::vector<float>(20, 0.1f), std::vector<float>(20, 0.12f));
    c.target = {1.3f, 0.7f, 0.0f};  // well off the curled tip, so the chain has to unroll
    c.solvers = {IkSolver::Ccd, IkSolver::Fabrik, IkSolver::JacobianDls};
    out.push_back(c);
  }
  {
    TeachingCase c;
    c.name = "hinge-limits";
    c.title = "Hinges limited to +-60 degrees";
    c.description =
        "Every joint may bend at most 60 degrees either way from its parent bone and the target needs the "
        "root near its limit: CCD's clamped turns crawl (tens of sweeps). FABRIK runs pure passes here (the "
        "library's DLS finish after 10 passes is off), clamping every joint as it goes; with limits its "
        "passes can crawl too, which is why the library normally hands over to DLS.";
    c.chain = seedChain();
    c.chain.limits.resize(4);
    const float l = glm::radians(60.0f);
    for (int j = 0; j < 3; ++j) c.chain.limits[j] = JointLimit::hinge({0.0f, 0.0f, 1.0f}, -l, l);
    c.target = {0.42f, 2.19f, 0.0f};
    c.solvers = {IkSolver::Ccd, IkSolver::Fabrik};
    c.settings.fabrikFinishAfter = 0;
    out.push_back(c);
  }
  // Pure FABRIK passes everywhere: the DLS finish only acts with limits (hinge-limits,
  // set above) and would hide the passes the figures are about.
  for (TeachingCase& c : out) c.settings.fabrikFinishAfter = 0;
  return out;
}

}  // namespace

const std::vector<TeachingCase>& teachingPresets() {
  static const std::vector<TeachingCase> presets = makePresets();
  return presets;
}

const TeachingCase* findTeachingPreset(const std::string& name) {
  for (const TeachingCase& c : teachingPresets())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace kinema
