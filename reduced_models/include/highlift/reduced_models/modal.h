// Modal analysis of a lumped torsional model: the generalised symmetric eigenproblem
// K v = w^2 M v with M = diag(J). It is solved as the standard problem A u = w^2 u with
// A = M^-1/2 K M^-1/2 and v = M^-1/2 u. When the spring graph is a set of chains (every node
// joined to at most two others, the usual shaft line and both wings through the PDU), A is
// tridiagonal in chain order: eigenvalues by Eigen's tridiagonal QR (O(n^2)), mode shapes by
// inverse iteration (O(n) each). Other trees use Eigen's dense SelfAdjointEigenSolver.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "highlift/reduced_models/lumped_model.h"

namespace highlift::reduced_models {

struct ModalOptions {
  std::vector<int> clamped;      ///< node indices held fixed (e.g. the PDU, a jammed station)
  int mode_shapes = 6;           ///< number of lowest mode shapes to compute; -1: all, 0: none
  double rigid_tolerance = 1e-9; ///< w^2 below tol * max w^2 counts as a rigid-body mode
};

struct ModalResult {
  std::vector<double> omega;     ///< rad/s, ascending; one per free node (rigid-body modes 0)
  Eigen::MatrixXd shapes;        ///< column k: mode k over all nodes, v^T M v = 1; clamped rows 0
  int rigid_body_modes = 0;      ///< modes with w^2 below the rigid tolerance
  bool tridiagonal = false;      ///< the chain path was used
  /// Lowest elastic eigenfrequency [rad/s]; 0 when there is none.
  double FirstElasticOmega() const;
};

/// Throws InputError when a free node has J <= 0 (names the node and the remedy).
ModalResult ComputeModes(const LumpedModel& model, const ModalOptions& options = {});

}  // namespace highlift::reduced_models
