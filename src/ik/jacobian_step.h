#pragma once
// One Jacobian IK step on an IkChain: the analytic Jacobian (axis x (effector - joint) per
// rotational degree of freedom, the axis itself for orientation rows), one 3-row block per
// target, solved by the transpose, the SVD pseudo-inverse, damped or selectively damped
// least squares. The Jacobian solvers loop over it; FABRIK finishes with it where its
// passes crawl (limits, several effectors). Internal to src/ik.
#include <Eigen/Dense>
#include <vector>

#include "ik/ik_chain.h"

namespace kinema::ik_detail {

enum class JacobianMethod { Transpose, Pinv, Dls, Sdls };

class JacobianStepper {
 public:
  // Fixes which slots move (every slot between a goal's root and its effector).
  JacobianStepper(const IkChain& c, JacobianMethod method);
  // Turns the joints by one step and refreshes the chain's world transforms. Returns false
  // (and changes nothing) when the step is not finite.
  bool step(IkChain& c, const IkSettings& settings);

 private:
  struct Dof {
    int slot;
    glm::vec3 axis;  // world axis, unit
  };
  void build(const IkChain& c);
  void apply(IkChain& c, const Eigen::VectorXf& dtheta);
  bool lineSearch(IkChain& c, const Eigen::VectorXf& direction, float alpha);
  Eigen::VectorXf sdls() const;

  JacobianMethod method_;
  std::vector<char> moves_;
  std::vector<Dof> dofs_;
  int rows_ = 0;
  float reach_ = 0.0f;
  float maxStep_ = glm::pi<float>();
  Eigen::MatrixXf j_;
  Eigen::VectorXf e_;
  std::vector<glm::quat> saved_;  // line search: the local rotations before a trial
};

}  // namespace kinema::ik_detail
