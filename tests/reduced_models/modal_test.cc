#include "highlift/reduced_models/modal.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "highlift/core/error.h"

namespace highlift::reduced_models {
namespace {

constexpr double kTight = 1e-9;  // relative tolerance for closed-form eigenvalues

LumpedModel FixedFreeChain(int n, double J, double c) {
  LumpedModel m;
  for (int i = 0; i < n; ++i) m.AddNode("m" + std::to_string(i), J);
  m.AddSpring(0, LumpedModel::kGround, c, "ground");
  for (int i = 1; i < n; ++i) m.AddSpring(i - 1, i, c, "s" + std::to_string(i));
  return m;
}

TEST(Modal, TwoMassOscillatorFrequency) {
  LumpedModel m;
  m.AddNode("a", 0.26);
  m.AddNode("b", 0.013);
  m.AddSpring(0, 1, 1914.0, "shaft");
  const ModalResult r = ComputeModes(m);
  ASSERT_EQ(r.omega.size(), 2u);
  EXPECT_EQ(r.rigid_body_modes, 1);
  EXPECT_EQ(r.omega[0], 0.0);
  const double expected = std::sqrt(1914.0 * (1.0 / 0.26 + 1.0 / 0.013));
  EXPECT_NEAR(r.FirstElasticOmega(), expected, kTight * expected);
}

TEST(Modal, UniformFixedFreeChainMatchesClosedForm) {
  const int n = 60;
  const double J = 0.013, c = 2188.0;
  const ModalResult r = ComputeModes(FixedFreeChain(n, J, c), {{}, 3});
  EXPECT_TRUE(r.tridiagonal);
  EXPECT_EQ(r.rigid_body_modes, 0);
  for (int k = 1; k <= n; ++k) {
    const double expected = 2.0 * std::sqrt(c / J) * std::sin((2 * k - 1) * std::numbers::pi / (2.0 * (2 * n + 1)));
    EXPECT_NEAR(r.omega[k - 1], expected, kTight * std::sqrt(c / J)) << "mode " << k;
  }
}

TEST(Modal, ClampingANodeEqualsAGroundSpring) {
  // A chain of n+1 nodes with node 0 clamped is the fixed-free chain of n nodes.
  LumpedModel m;
  for (int i = 0; i <= 10; ++i) m.AddNode("m" + std::to_string(i), 0.5);
  for (int i = 1; i <= 10; ++i) m.AddSpring(i - 1, i, 100.0, "s");
  const ModalResult clamped = ComputeModes(m, {{0}, 0});
  const ModalResult reference = ComputeModes(FixedFreeChain(10, 0.5, 100.0), {{}, 0});
  ASSERT_EQ(clamped.omega.size(), 10u);
  for (int k = 0; k < 10; ++k) EXPECT_NEAR(clamped.omega[k], reference.omega[k], 1e-10 * reference.omega[9]);
}

void ExpectEigenpairs(const LumpedModel& m, const ModalResult& r, int clamped = -1) {
  const int n = static_cast<int>(m.nodes.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (const auto& s : m.springs) {
    K(s.a, s.a) += s.c;
    if (s.b >= 0) {
      K(s.b, s.b) += s.c;
      K(s.a, s.b) -= s.c;
      K(s.b, s.a) -= s.c;
    }
  }
  Eigen::VectorXd M(n);
  for (int i = 0; i < n; ++i) M[i] = m.nodes[i].J;
  const double scale = K.cwiseAbs().maxCoeff();
  for (int k = 0; k < r.shapes.cols(); ++k) {
    const Eigen::VectorXd v = r.shapes.col(k);
    const double w2 = r.omega[k] * r.omega[k];
    Eigen::VectorXd residual = K * v - w2 * M.asDiagonal() * v;
    if (clamped >= 0) residual[clamped] = 0.0;  // the reaction at the clamp
    EXPECT_LT(residual.norm(), 1e-8 * scale * v.norm()) << "mode " << k;
    for (int j = 0; j <= k; ++j) {
      const double product = r.shapes.col(j).dot(M.asDiagonal() * v);
      EXPECT_NEAR(product, j == k ? 1.0 : 0.0, 1e-8) << "modes " << j << ", " << k;
    }
  }
}

TEST(Modal, ChainModeShapesAreMassOrthonormalEigenvectors) {
  LumpedModel m;
  for (int i = 0; i < 300; ++i) m.AddNode("m", 0.01 + 0.005 * std::sin(0.3 * i) + (i == 0 ? 0.26 : 0.0));
  for (int i = 1; i < 300; ++i) m.AddSpring(i - 1, i, 2000.0 + 500.0 * std::cos(0.7 * i), "s");
  const ModalResult r = ComputeModes(m, {{}, 8});
  EXPECT_TRUE(r.tridiagonal);
  EXPECT_EQ(r.rigid_body_modes, 1);
  ExpectEigenpairs(m, r);
}

TEST(Modal, TreeUsesDenseSolverWithTheSameEigenpairs) {
  // A shaft line with a station branch at every node: not a chain.
  LumpedModel m;
  const int hub = m.AddNode("pdu", 0.26);
  int previous = hub;
  for (int i = 0; i < 6; ++i) {
    const int station = m.AddNode("s" + std::to_string(i), 0.002);
    const int flap = m.AddNode("f" + std::to_string(i), 0.01);
    m.AddSpring(previous, station, 2000.0, "shaft");
    m.AddSpring(station, flap, 5000.0, "limiter");
    previous = station;
  }
  const ModalResult r = ComputeModes(m, {{hub}, -1});
  EXPECT_FALSE(r.tridiagonal);
  EXPECT_EQ(r.omega.size(), 12u);
  EXPECT_EQ(r.rigid_body_modes, 0);
  ExpectEigenpairs(m, r, hub);
  EXPECT_EQ(r.shapes.row(hub).norm(), 0.0);
}

TEST(Modal, NodeWithoutInertiaIsAnInputErrorNamingIt) {
  LumpedModel m;
  m.AddNode("gbx_l1", 0.0);
  m.AddNode("b", 1.0);
  m.AddSpring(0, 1, 10.0, "s");
  try {
    ComputeModes(m);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node 'gbx_l1' has no inertia"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace highlift::reduced_models
