#include "highlift/reduced_models/modal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/Eigenvalues>

#include "highlift/core/error.h"
#include "highlift/core/message_number.h"

namespace highlift::reduced_models {
namespace {

/// Solves (T - sigma I) x = b in place for symmetric tridiagonal T (diagonal d, off-diagonal e)
/// by Gaussian elimination with partial pivoting (LAPACK dgttrf/dgtts2); zero pivots are
/// replaced by `tiny`, which is what inverse iteration wants near an eigenvalue.
class ShiftedTridiagonalSolver {
 public:
  ShiftedTridiagonalSolver(const Eigen::VectorXd& d, const Eigen::VectorXd& e, double sigma, double tiny)
      : n_(d.size()), d_(d.array() - sigma), dl_(e), du_(e), du2_(Eigen::VectorXd::Zero(std::max<Eigen::Index>(n_ - 1, 0))),
        swap_(std::max<Eigen::Index>(n_ - 1, 0), false) {
    for (Eigen::Index i = 0; i + 1 < n_; ++i) {
      if (std::abs(d_[i]) >= std::abs(dl_[i])) {
        if (d_[i] == 0.0) d_[i] = tiny;
        const double fact = dl_[i] / d_[i];
        dl_[i] = fact;
        d_[i + 1] -= fact * du_[i];
      } else {
        const double fact = d_[i] / dl_[i];
        d_[i] = dl_[i];
        dl_[i] = fact;
        const double temp = du_[i];
        du_[i] = d_[i + 1];
        d_[i + 1] = temp - fact * d_[i + 1];
        if (i + 2 < n_) {
          du2_[i] = du_[i + 1];
          du_[i + 1] = -fact * du_[i + 1];
        }
        swap_[i] = true;
      }
    }
    if (n_ > 0 && d_[n_ - 1] == 0.0) d_[n_ - 1] = tiny;
  }

  void Solve(Eigen::VectorXd& b) const {
    for (Eigen::Index i = 0; i + 1 < n_; ++i) {
      if (!swap_[i]) {
        b[i + 1] -= dl_[i] * b[i];
      } else {
        const double temp = b[i];
        b[i] = b[i + 1];
        b[i + 1] = temp - dl_[i] * b[i];
      }
    }
    b[n_ - 1] /= d_[n_ - 1];
    if (n_ > 1) b[n_ - 2] = (b[n_ - 2] - du_[n_ - 2] * b[n_ - 1]) / d_[n_ - 2];
    for (Eigen::Index i = n_ - 3; i >= 0; --i)
      b[i] = (b[i] - du_[i] * b[i + 1] - du2_[i] * b[i + 2]) / d_[i];
  }

 private:
  Eigen::Index n_;
  Eigen::VectorXd d_, dl_, du_, du2_;
  std::vector<bool> swap_;
};

/// Eigenvectors of tridiagonal T for the given (accurate) eigenvalues, by inverse iteration with
/// re-orthogonalisation against vectors of close eigenvalues (as LAPACK dstein does).
Eigen::MatrixXd TridiagonalEigenvectors(const Eigen::VectorXd& d, const Eigen::VectorXd& e,
                                        const Eigen::VectorXd& lambda, int count) {
  const Eigen::Index n = d.size();
  const double norm = std::max(d.cwiseAbs().maxCoeff() + 2.0 * (e.size() ? e.cwiseAbs().maxCoeff() : 0.0),
                               std::numeric_limits<double>::min());
  const double eps = std::numeric_limits<double>::epsilon();
  Eigen::MatrixXd vectors(n, count);
  for (int k = 0; k < count; ++k) {
    const double sigma = lambda[k];
    ShiftedTridiagonalSolver solver(d, e, sigma, eps * norm);
    Eigen::VectorXd x(n);
    for (Eigen::Index i = 0; i < n; ++i) x[i] = 1.0 + 0.1 * std::sin(1.0 + 0.7 * static_cast<double>(i));
    x.normalize();
    for (int iteration = 0; iteration < 4; ++iteration) {
      solver.Solve(x);
      for (int j = 0; j < k; ++j)
        if (std::abs(lambda[j] - sigma) < 1e-3 * norm) x -= vectors.col(j).dot(x) * vectors.col(j);
      const double length = x.norm();
      HIGHLIFT_CHECK(std::isfinite(length) && length > 0.0, "inverse iteration broke down");
      x /= length;
    }
    // Fixed sign: the largest entry positive, so shapes are reproducible.
    Eigen::Index at = 0;
    x.cwiseAbs().maxCoeff(&at);
    if (x[at] < 0.0) x = -x;
    vectors.col(k) = x;
  }
  return vectors;
}

}  // namespace

double ModalResult::FirstElasticOmega() const {
  return rigid_body_modes < static_cast<int>(omega.size()) ? omega[rigid_body_modes] : 0.0;
}

ModalResult ComputeModes(const LumpedModel& model, const ModalOptions& options) {
  const int total = static_cast<int>(model.nodes.size());
  std::vector<int> index(total, 0);  // node -> free index, -1 if clamped
  for (int c : options.clamped) {
    HIGHLIFT_CHECK(c >= 0 && c < total, "clamped node index out of range");
    index[c] = -1;
  }
  std::vector<int> node_of;
  for (int i = 0; i < total; ++i)
    if (index[i] == 0) {
      index[i] = static_cast<int>(node_of.size());
      node_of.push_back(i);
    }
  const int n = static_cast<int>(node_of.size());
  ModalResult result;
  if (n == 0) return result;
  for (int i : node_of)
    if (!(model.nodes[i].J > 0.0))
      throw InputError("lumped model node '" + model.nodes[i].name +
                       "' has no inertia (J = " + FormatMessageNumber(model.nodes[i].J) +
                       " kg*m^2); give the component there an inertia or use a reduced model that "
                       "merges it");

  // Stiffness: diagonal and the off-diagonal couplings between free nodes (parallel springs summed).
  Eigen::VectorXd k_diagonal = Eigen::VectorXd::Zero(n);
  std::map<std::pair<int, int>, double> coupling;
  for (const auto& s : model.springs) {
    const int a = index[s.a];
    const int b = s.b == LumpedModel::kGround ? -1 : index[s.b];
    if (a >= 0) k_diagonal[a] += s.c;
    if (b >= 0) k_diagonal[b] += s.c;
    if (a >= 0 && b >= 0 && a != b) coupling[{std::min(a, b), std::max(a, b)}] -= s.c;
  }
  Eigen::VectorXd inv_sqrt_J(n);
  for (int i = 0; i < n; ++i) inv_sqrt_J[i] = 1.0 / std::sqrt(model.nodes[node_of[i]].J);

  // Chain detection: every free node has at most two neighbours and there is no cycle (the
  // lumped model is a forest by construction, so a node with <= 2 neighbours is on a path).
  std::vector<std::vector<std::pair<int, double>>> neighbours(n);
  for (const auto& [pair, value] : coupling) {
    neighbours[pair.first].push_back({pair.second, value});
    neighbours[pair.second].push_back({pair.first, value});
  }
  bool chain = true;
  for (const auto& list : neighbours) chain = chain && list.size() <= 2;
  std::vector<int> order;
  if (chain) {
    std::vector<bool> seen(n, false);
    for (int start = 0; start < n && chain; ++start) {
      if (seen[start] || neighbours[start].size() == 2) continue;
      int at = start, previous = -1;
      while (at >= 0) {
        seen[at] = true;
        order.push_back(at);
        int next = -1;
        for (const auto& [other, value] : neighbours[at])
          if (other != previous) next = other;
        previous = at;
        at = next;
      }
    }
    chain = static_cast<int>(order.size()) == n;  // otherwise a cycle: use the dense path
  }

  const int shapes_wanted = options.mode_shapes < 0 ? n : std::min(options.mode_shapes, n);
  Eigen::VectorXd lambda;
  Eigen::MatrixXd u;  // eigenvectors of A in free-node order
  if (chain) {
    result.tridiagonal = true;
    std::vector<int> position(n);
    for (int p = 0; p < n; ++p) position[order[p]] = p;
    Eigen::VectorXd diagonal(n), off(std::max(n - 1, 0));
    off.setZero();
    for (int p = 0; p < n; ++p) {
      const int i = order[p];
      diagonal[p] = k_diagonal[i] * inv_sqrt_J[i] * inv_sqrt_J[i];
    }
    for (const auto& [pair, value] : coupling) {
      const int p = std::min(position[pair.first], position[pair.second]);
      off[p] = value * inv_sqrt_J[pair.first] * inv_sqrt_J[pair.second];
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
    if (n == 1) {
      lambda = diagonal;
    } else {
      solver.computeFromTridiagonal(diagonal, off, Eigen::EigenvaluesOnly);
      HIGHLIFT_CHECK(solver.info() == Eigen::Success, "tridiagonal eigenvalue iteration did not converge");
      lambda = solver.eigenvalues();
    }
    if (shapes_wanted > 0) {
      const Eigen::MatrixXd chain_vectors = TridiagonalEigenvectors(diagonal, off, lambda, shapes_wanted);
      u.resize(n, shapes_wanted);
      for (int p = 0; p < n; ++p) u.row(order[p]) = chain_vectors.row(p);
    }
  } else {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) A(i, i) = k_diagonal[i] * inv_sqrt_J[i] * inv_sqrt_J[i];
    for (const auto& [pair, value] : coupling) {
      const double a = value * inv_sqrt_J[pair.first] * inv_sqrt_J[pair.second];
      A(pair.first, pair.second) = a;
      A(pair.second, pair.first) = a;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        A, shapes_wanted > 0 ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
    HIGHLIFT_CHECK(solver.info() == Eigen::Success, "symmetric eigenvalue iteration did not converge");
    lambda = solver.eigenvalues();
    if (shapes_wanted > 0) {
      u = solver.eigenvectors().leftCols(shapes_wanted);
      for (int k = 0; k < shapes_wanted; ++k) {
        Eigen::Index at = 0;
        u.col(k).cwiseAbs().maxCoeff(&at);
        if (u(at, k) < 0.0) u.col(k) = -u.col(k);
      }
    }
  }

  const double largest = std::max(lambda.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  result.omega.resize(n);
  for (int k = 0; k < n; ++k) {
    const double value = lambda[k] < options.rigid_tolerance * largest ? 0.0 : lambda[k];
    if (value == 0.0) ++result.rigid_body_modes;
    result.omega[k] = std::sqrt(value);
  }
  result.shapes = Eigen::MatrixXd::Zero(total, shapes_wanted);
  for (int k = 0; k < shapes_wanted; ++k)
    for (int i = 0; i < n; ++i) result.shapes(node_of[i], k) = u(i, k) * inv_sqrt_J[i];
  return result;
}

}  // namespace highlift::reduced_models
