// The linear solver that eliminates the angle and twist states before KLU factors the rest
// (sim/src/reduced_klu.h): which states it eliminates, and that its solutions are those of the
// whole system, also where a matrix breaks its assumption.
#include "reduced_klu.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <vector>

namespace highlift::sim::detail {
namespace {

using Rows = std::vector<std::optional<std::vector<int>>>;

/// A compressed-column pattern from a dense 0/1 matrix given row by row.
void Pattern(const std::vector<std::vector<int>>& dense, std::vector<int>& colptr, std::vector<int>& rows) {
  const int n = static_cast<int>(dense.size());
  colptr.assign(1, 0);
  rows.clear();
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i)
      if (dense[i][j] != 0 || i == j) rows.push_back(i);
    colptr.push_back(static_cast<int>(rows.size()));
  }
}

// Two inertias and the spring between them: states phi1, w1, phi2, w2, phi_rel. Every state
// shares the spring's clique, so the pattern is full. The angles depend on their speeds, the
// twist on both speeds: all three are eliminated, and KLU factors the 2 x 2 of the speeds.
TEST(ReducedKlu, EliminatesTheAnglesAndTheTwistOfTwoInertiasOnASpring) {
  std::vector<int> colptr, rows;
  Pattern(std::vector<std::vector<int>>(5, std::vector<int>(5, 1)), colptr, rows);
  const Rows speed_rows{std::vector<int>{1}, std::nullopt, std::vector<int>{3}, std::nullopt, std::vector<int>{1, 3}};
  EXPECT_EQ(EliminatedStates(colptr, rows, speed_rows), (std::vector<char>{1, 0, 1, 0, 1}));
}

// A state whose elimination would add an entry stays: the twist t depends on w1 and w2, and
// w3 depends on t but is not coupled to w1 in the pattern, so M(w3, t) M(t, w1) would fill.
TEST(ReducedKlu, KeepsAStateWhoseEliminationWouldFill) {
  // states: w1, w2, w3, t
  const std::vector<std::vector<int>> dense{{1, 1, 0, 1}, {1, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
  std::vector<int> colptr, rows;
  Pattern(dense, colptr, rows);
  const Rows speed_rows{std::nullopt, std::nullopt, std::nullopt, std::vector<int>{0, 1}};
  EXPECT_EQ(EliminatedStates(colptr, rows, speed_rows), (std::vector<char>{0, 0, 0, 0}));
  // With w3 coupled to w1 and w2 it goes.
  std::vector<std::vector<int>> coupled = dense;
  coupled[2][0] = coupled[0][2] = coupled[2][1] = coupled[1][2] = 1;
  Pattern(coupled, colptr, rows);
  EXPECT_EQ(EliminatedStates(colptr, rows, speed_rows), (std::vector<char>{0, 0, 0, 1}));
  // A state in another's speed row is not eliminated itself, nor one whose row names a state
  // out of range.
  const Rows chained{std::vector<int>{1}, std::nullopt, std::nullopt, std::vector<int>{0}};
  EXPECT_EQ(EliminatedStates(colptr, rows, chained), (std::vector<char>{1, 0, 0, 0}));
  const Rows out_of_range{std::nullopt, std::nullopt, std::nullopt, std::vector<int>{7}};
  EXPECT_EQ(EliminatedStates(colptr, rows, out_of_range), (std::vector<char>{0, 0, 0, 0}));
}

/// A chain of `nodes` inertias coupled by spring-dampers: per node (phi, w), per spring a twist,
/// in that order (node i: 2i, 2i + 1; spring i between nodes i and i + 1: 2 nodes + i). The
/// pattern is the simulator's: the cliques of each spring's footprint and of each node's
/// elements.
struct Chain {
  int nodes, n;
  std::vector<std::vector<int>> dense;
  Rows speed_rows;
  explicit Chain(int nodes_) : nodes(nodes_), n(3 * nodes_ - 1), dense(n, std::vector<int>(n, 0)), speed_rows(n) {
    auto clique = [&](const std::vector<int>& c) {
      for (int a : c)
        for (int b : c) dense[a][b] = 1;
    };
    for (int s = 0; s + 1 < nodes; ++s) {
      const int t = 2 * nodes + s;
      std::vector<int> footprint{2 * s, 2 * s + 1, 2 * s + 2, 2 * s + 3, t};
      clique(footprint);
      // the node cliques: every element's footprint on node s + 1 together
      if (s + 2 < nodes) clique({2 * s, 2 * s + 1, 2 * s + 2, 2 * s + 3, t, 2 * s + 4, 2 * s + 5, t + 1});
      speed_rows[t] = std::vector<int>{2 * s + 1, 2 * s + 3};
    }
    for (int i = 0; i < nodes; ++i) speed_rows[2 * i] = std::vector<int>{2 * i + 1};
  }
  /// M = I - gamma J of that structure (Jacobian below).
  Eigen::MatrixXd Matrix(std::mt19937& rng, double gamma) const {
    return Eigen::MatrixXd::Identity(n, n) - gamma * Jacobian(rng);
  }
  /// J with random values: angle rows the speed, twist rows the speed difference, speed rows
  /// random on the pattern.
  Eigen::MatrixXd Jacobian(std::mt19937& rng) const {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < nodes; ++i) J(2 * i, 2 * i + 1) = 1.0;
    for (int s = 0; s + 1 < nodes; ++s) {
      J(2 * nodes + s, 2 * s + 1) = -1.0;
      J(2 * nodes + s, 2 * s + 3) = 1.0;
    }
    for (int i = 0; i < nodes; ++i)
      for (int j = 0; j < n; ++j)
        if (dense[2 * i + 1][j] != 0) J(2 * i + 1, j) = 50.0 * u(rng);
    return J;
  }
};

class SolverFixture {
 public:
  SolverFixture(const std::vector<int>& colptr, const std::vector<int>& rows, const Rows& speed_rows)
      : colptr_(colptr), rows_(rows), n_(static_cast<int>(colptr.size()) - 1) {
    SUNContext_Create(nullptr, &ctx_);
    A_ = SUNSparseMatrix(n_, n_, static_cast<sunindextype>(rows.size()), CSC_MAT, ctx_);
    for (int j = 0; j <= n_; ++j) SUNSparseMatrix_IndexPointers(A_)[j] = colptr[j];
    for (std::size_t k = 0; k < rows.size(); ++k) SUNSparseMatrix_IndexValues(A_)[k] = rows[k];
    x_ = N_VNew_Serial(n_, ctx_);
    b_ = N_VNew_Serial(n_, ctx_);
    ls_ = NewReducedKlu(colptr, rows, speed_rows, ctx_);
  }
  SolverFixture(const SolverFixture&) = delete;
  SolverFixture& operator=(const SolverFixture&) = delete;
  ~SolverFixture() {
    if (ls_ != nullptr) SUNLinSolFree(ls_);
    N_VDestroy(x_);
    N_VDestroy(b_);
    SUNMatDestroy(A_);
    SUNContext_Free(&ctx_);
  }
  SUNLinearSolver solver() const { return ls_; }
  /// Sets A to M on the pattern (entries of M outside it must be 0), sets the solver up and
  /// solves M x = b; returns the largest |x - x_dense| relative to the largest |x_dense|.
  double SolveError(const Eigen::MatrixXd& M, const Eigen::VectorXd& b, int* setup_flag = nullptr) {
    for (int j = 0; j < n_; ++j)
      for (int k = colptr_[j]; k < colptr_[j + 1]; ++k) SUNSparseMatrix_Data(A_)[k] = M(rows_[k], j);
    const int flag = SUNLinSolSetup(ls_, A_);
    if (setup_flag != nullptr) *setup_flag = flag;
    if (flag != SUNLS_SUCCESS) return INFINITY;
    for (int i = 0; i < n_; ++i) NV_Ith_S(b_, i) = b(i);
    if (SUNLinSolSolve(ls_, A_, x_, b_, 0.0) != SUNLS_SUCCESS) return INFINITY;
    const Eigen::VectorXd exact = M.fullPivLu().solve(b);
    double error = 0.0;
    for (int i = 0; i < n_; ++i) error = std::max(error, std::abs(NV_Ith_S(x_, i) - exact(i)));
    return error / exact.cwiseAbs().maxCoeff();
  }
  /// Solves (I - gamma*J) x = b with the solver given J and gamma (ReducedKluSetGamma, as CVODE's
  /// linear-system function in the simulator does) or, when `given_jacobian` is false, given
  /// I - gamma*J as SUNDIALS' own SUNMatScaleAddI forms it from J. False when a call fails.
  bool SolveFrom(const Eigen::MatrixXd& J, double gamma, bool given_jacobian, const Eigen::VectorXd& b,
                 Eigen::VectorXd& x) {
    for (int j = 0; j < n_; ++j)
      for (int k = colptr_[j]; k < colptr_[j + 1]; ++k) SUNSparseMatrix_Data(A_)[k] = J(rows_[k], j);
    if (given_jacobian) ReducedKluSetGamma(ls_, gamma);
    else if (SUNMatScaleAddI_Sparse(-gamma, A_) != SUNMAT_SUCCESS) return false;
    if (SUNLinSolSetup(ls_, A_) != SUNLS_SUCCESS) return false;
    for (int i = 0; i < n_; ++i) NV_Ith_S(b_, i) = b(i);
    if (SUNLinSolSolve(ls_, A_, x_, b_, 0.0) != SUNLS_SUCCESS) return false;
    x.resize(n_);
    for (int i = 0; i < n_; ++i) x(i) = NV_Ith_S(x_, i);
    return true;
  }

 private:
  std::vector<int> colptr_, rows_;
  int n_;
  SUNContext ctx_ = nullptr;
  SUNMatrix A_ = nullptr;
  N_Vector x_ = nullptr, b_ = nullptr;
  SUNLinearSolver ls_ = nullptr;
};

/// A chain, its pattern and a solver for it.
struct ChainSolver {
  explicit ChainSolver(int nodes) : chain(nodes) {
    Pattern(chain.dense, colptr, rows);
    fixture = std::make_unique<SolverFixture>(colptr, rows, chain.speed_rows);
  }
  Chain chain;
  std::vector<int> colptr, rows;
  std::unique_ptr<SolverFixture> fixture;
};

// Against a dense LU of the whole matrix, over several setups (the first factorisation, then
// KLU's refactorisations on its pivot order) with gammas from 1e-6 to 1e-2.
TEST(ReducedKlu, SolutionsAreThoseOfTheWholeSystem) {
  ChainSolver s(12);
  const Chain& chain = s.chain;
  SolverFixture& fixture = *s.fixture;
  const std::vector<char> eliminated = EliminatedStates(s.colptr, s.rows, chain.speed_rows);
  int count = 0;
  for (char e : eliminated) count += e;
  EXPECT_EQ(count, 12 + 11);  // every angle and every twist
  ASSERT_NE(fixture.solver(), nullptr);
  EXPECT_EQ(ReducedKluSize(fixture.solver()), 12);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double gamma : {1e-6, 1e-4, 1e-3, 3e-3, 1e-2}) {
    const Eigen::MatrixXd M = chain.Matrix(rng, gamma);
    Eigen::VectorXd b(chain.n);
    for (int i = 0; i < chain.n; ++i) b(i) = u(rng);
    EXPECT_LT(fixture.SolveError(M, b), 1e-12) << "gamma " << gamma;
  }
  EXPECT_EQ(ReducedKluFullSetups(fixture.solver()), 0);
}

// Given J and gamma, the solver forms I - gamma*J itself as it reads J (the simulator keeps the
// Jacobian in CVODE's matrix between its evaluations): the same solutions to the last bit as
// when it is given the matrix that SUNDIALS' SUNMatScaleAddI forms, over a sequence of setups
// with new Jacobians and new gammas on one solver each, also where the matrix is factored whole.
// A setup without ReducedKluSetGamma reads its matrix as I - gamma*J again.
TEST(ReducedKlu, GivenTheJacobianAndGammaItSolvesAsGivenIMinusGammaJ) {
  ChainSolver from_jacobian(12), from_matrix(12);
  const Chain& chain = from_jacobian.chain;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd J = chain.Jacobian(rng);
  for (double gamma : {1e-5, 1e-3, 2e-3, 3e-2}) {
    if (gamma > 1e-3) J = chain.Jacobian(rng);  // a new Jacobian, or the same with a new gamma
    Eigen::VectorXd b(chain.n), x_jacobian, x_matrix;
    for (int i = 0; i < chain.n; ++i) b(i) = u(rng);
    ASSERT_TRUE(from_jacobian.fixture->SolveFrom(J, gamma, true, b, x_jacobian));
    ASSERT_TRUE(from_matrix.fixture->SolveFrom(J, gamma, false, b, x_matrix));
    for (int i = 0; i < chain.n; ++i) EXPECT_EQ(x_jacobian(i), x_matrix(i)) << "gamma " << gamma << ", state " << i;
  }
  // A Jacobian outside the assumption (an angle's row reads another speed): both factor the
  // whole matrix, with the same solutions.
  J(0, 3) = 0.5;
  Eigen::VectorXd x_jacobian, x_matrix;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(chain.n, -1.0, 1.0);
  ASSERT_TRUE(from_jacobian.fixture->SolveFrom(J, 2e-3, true, b, x_jacobian));
  ASSERT_TRUE(from_matrix.fixture->SolveFrom(J, 2e-3, false, b, x_matrix));
  for (int i = 0; i < chain.n; ++i) EXPECT_EQ(x_jacobian(i), x_matrix(i)) << "whole, state " << i;
  EXPECT_EQ(ReducedKluFullSetups(from_jacobian.fixture->solver()), 1);
  EXPECT_EQ(ReducedKluFullSetups(from_matrix.fixture->solver()), 1);
  const Eigen::MatrixXd M = chain.Matrix(rng, 1e-3);
  EXPECT_LT(from_jacobian.fixture->SolveError(M, Eigen::VectorXd::Ones(chain.n)), 1e-12);
  EXPECT_EQ(ReducedKluFullSetups(from_jacobian.fixture->solver()), 1);
}

// An eliminated state whose row reads three speeds (as a differential's angle would), beside the
// angles (one speed) and the twists (two): the back substitution takes each length of row in a
// loop of its own, and every one gives the whole system's solution.
TEST(ReducedKlu, RowsOfOneTwoAndThreeSpeedsSolveAsTheWholeSystem) {
  const Chain chain(6);
  const int k = chain.n, n = chain.n + 1;  // the new state, last
  std::vector<std::vector<int>> dense(n, std::vector<int>(n, 0));
  for (int i = 0; i < chain.n; ++i)
    for (int j = 0; j < chain.n; ++j) dense[i][j] = chain.dense[i][j];
  const std::vector<int> footprint{1, 3, 5, 9, k};  // the speeds it reads and those it drives
  for (int a : footprint)
    for (int b : footprint) dense[a][b] = 1;
  Rows speed_rows = chain.speed_rows;
  speed_rows.push_back(std::vector<int>{1, 5, 9});
  std::vector<int> colptr, rows;
  Pattern(dense, colptr, rows);
  const std::vector<char> eliminated = EliminatedStates(colptr, rows, speed_rows);
  ASSERT_EQ(eliminated[k], 1);
  int count = 0;
  for (char e : eliminated) count += e;
  EXPECT_EQ(count, 6 + 5 + 1);  // the angles, the twists and the new state
  SolverFixture fixture(colptr, rows, speed_rows);
  ASSERT_NE(fixture.solver(), nullptr);
  EXPECT_EQ(ReducedKluSize(fixture.solver()), 6);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double gamma : {1e-5, 1e-3, 1e-2}) {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
    J.topLeftCorner(chain.n, chain.n) = chain.Jacobian(rng);
    J(k, 1) = 1.0;
    J(k, 5) = 1.0;
    J(k, 9) = -2.0;
    for (int v : {1, 3, 5, 9}) J(v, k) = 50.0 * u(rng);  // it drives node speeds
    const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(n, n) - gamma * J;
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) b(i) = u(rng);
    EXPECT_LT(fixture.SolveError(M, b), 1e-12) << "gamma " << gamma;
  }
  EXPECT_EQ(ReducedKluFullSetups(fixture.solver()), 0);
}

/// Four inertias on three springs, with a solver.
class ReducedKluOnFourInertias : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_NE(fixture.solver(), nullptr); }
  ChainSolver s{4};
  const Chain& chain = s.chain;
  SolverFixture& fixture = *s.fixture;
};

// A matrix whose eliminated row holds an entry outside its speed row (an angle that a law reads
// back into its own derivative) is not what the reduction assumes: that setup factors the whole
// matrix, and the solution is still the whole system's. The next matrix of the assumed form is
// reduced again.
TEST_F(ReducedKluOnFourInertias, AMatrixOutsideTheAssumptionIsFactoredWhole) {
  std::mt19937 rng(11);
  Eigen::MatrixXd M = chain.Matrix(rng, 1e-3);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(chain.n, -1.0, 2.0);
  EXPECT_LT(fixture.SolveError(M, b), 1e-12);
  EXPECT_EQ(ReducedKluFullSetups(fixture.solver()), 0);
  M(0, 3) = 0.25;  // phi1 reads w2
  EXPECT_LT(fixture.SolveError(M, b), 1e-12);
  EXPECT_EQ(ReducedKluFullSetups(fixture.solver()), 1);
  M(0, 3) = 0.0;
  M(2 * chain.nodes, 2 * chain.nodes) = 0.0;  // a twist's diagonal vanishes: cannot be eliminated
  EXPECT_LT(fixture.SolveError(M, b), 1e-12);
  EXPECT_EQ(ReducedKluFullSetups(fixture.solver()), 2);
  M(2 * chain.nodes, 2 * chain.nodes) = 1.0;
  EXPECT_LT(fixture.SolveError(M, b), 1e-12);
  EXPECT_EQ(ReducedKluFullSetups(fixture.solver()), 2);
}

// A singular matrix fails the setup recoverably (CVODE then retries with a smaller step), and
// the next regular one is factored afresh.
TEST_F(ReducedKluOnFourInertias, ASingularMatrixFailsRecoverablyAndTheNextIsFactoredAfresh) {
  std::mt19937 rng(3);
  const Eigen::MatrixXd M = chain.Matrix(rng, 1e-3);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(chain.n);
  EXPECT_LT(fixture.SolveError(M, b), 1e-12);
  Eigen::MatrixXd singular = M;
  for (int j = 0; j < chain.n; ++j) singular(3, j) = singular(1, j);  // w2's row = w1's
  int flag = SUNLS_SUCCESS;
  fixture.SolveError(singular, b, &flag);
  EXPECT_EQ(flag, SUNLS_PACKAGE_FAIL_REC);
  EXPECT_LT(fixture.SolveError(M, b, &flag), 1e-12);
  EXPECT_EQ(flag, SUNLS_SUCCESS);
}

// No state to eliminate: no solver (the simulator then uses SUNLinSol_KLU).
TEST(ReducedKlu, NothingToEliminateGivesNoSolver) {
  std::vector<int> colptr, rows;
  Pattern(std::vector<std::vector<int>>(3, std::vector<int>(3, 1)), colptr, rows);
  SUNContext ctx = nullptr;
  SUNContext_Create(nullptr, &ctx);
  EXPECT_EQ(NewReducedKlu(colptr, rows, Rows(3), ctx), nullptr);
  SUNContext_Free(&ctx);
}

}  // namespace
}  // namespace highlift::sim::detail
