// The simulator's sparse LU (sim/src/sparse_lu.h) against a dense LU with partial pivoting, on
// matrices of the drive models' kind: M = I - gamma J on a structurally symmetric pattern of
// node-group cliques along a chain, rows of very different scales; against SUNLinSol_KLU bit for
// bit. Also the refactorisation on the fixed order and its guards (a zero pivot, a singular
// matrix: SUNLS_PACKAGE_FAIL_REC, then a fresh pivoting) and a new pattern.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cstring>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "sparse_lu.h"

namespace highlift::sim::detail {
namespace {

/// A square matrix by its entries, turned into a CSC SUNMatrix (and back into a dense one).
struct Pattern {
  int n = 0;
  std::set<std::pair<int, int>> entries;  ///< (column, row)
};

/// Drive-model-like pattern: every node (2 states, angle and speed) couples to itself and to its
/// neighbours on a chain; a few random groups of 3 to 6 nearby nodes form cliques (the node
/// groups of gearboxes and brakes).
Pattern DrivePattern(int nodes, std::mt19937& rng) {
  Pattern p;
  p.n = 2 * nodes;
  auto couple = [&](int a, int b) {
    for (int i : {2 * a, 2 * a + 1})
      for (int j : {2 * b, 2 * b + 1}) {
        p.entries.insert({i, j});
        p.entries.insert({j, i});
      }
  };
  for (int a = 0; a < nodes; ++a) {
    couple(a, a);
    if (a + 1 < nodes) couple(a, a + 1);
  }
  std::uniform_int_distribution<int> start(0, nodes - 1), size(3, 6), offset(-8, 8);
  for (int g = 0; g < nodes / 6; ++g) {
    std::vector<int> group;
    const int centre = start(rng);
    for (int m = size(rng); m > 0; --m) group.push_back(std::clamp(centre + offset(rng), 0, nodes - 1));
    for (int a : group)
      for (int b : group) couple(a, b);
  }
  return p;
}

class Csc {
 public:
  Csc(const Pattern& p, SUNContext context) : n_(p.n) {
    A_ = SUNSparseMatrix(n_, n_, static_cast<sunindextype>(p.entries.size()), CSC_MAT, context);
    sunindextype* colptr = SUNSparseMatrix_IndexPointers(A_);
    sunindextype* rows = SUNSparseMatrix_IndexValues(A_);
    sunindextype k = 0;
    int column = 0;
    colptr[0] = 0;
    for (const auto& [j, i] : p.entries) {
      while (column < j) colptr[++column] = k;
      rows[k++] = i;
    }
    while (column < n_) colptr[++column] = k;
  }
  ~Csc() { SUNMatDestroy(A_); }
  Csc(const Csc&) = delete;
  Csc& operator=(const Csc&) = delete;
  SUNMatrix get() const { return A_; }

  /// Sets the values to f(row, column) and returns the dense matrix.
  template <class F>
  Eigen::MatrixXd Fill(F f) {
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n_, n_);
    const sunindextype* colptr = SUNSparseMatrix_IndexPointers(A_);
    const sunindextype* rows = SUNSparseMatrix_IndexValues(A_);
    double* values = SUNSparseMatrix_Data(A_);
    for (int j = 0; j < n_; ++j)
      for (sunindextype k = colptr[j]; k < colptr[j + 1]; ++k) {
        const int i = static_cast<int>(rows[k]);
        values[k] = f(i, j);
        dense(i, j) = values[k];
      }
    return dense;
  }

 private:
  int n_;
  SUNMatrix A_ = nullptr;
};

class SparseLuTest : public ::testing::Test {
 protected:
  void TearDown() override {
    if (solver_ != nullptr) SUNLinSolFree(solver_);
  }

  /// Solves dense * x = b with the solver (after a successful setup) and compares with the dense
  /// LU's solution: the largest difference relative to the largest component of x.
  double SolveError(const Eigen::MatrixXd& dense, Csc& A, std::mt19937& rng) {
    const int n = static_cast<int>(dense.rows());
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) b(i) = u(rng);
    const Eigen::VectorXd expected = dense.partialPivLu().solve(b);
    N_Vector x = N_VNew_Serial(n, context_), rhs = N_VNew_Serial(n, context_);
    for (int i = 0; i < n; ++i) NV_Ith_S(rhs, i) = b(i);
    EXPECT_EQ(SUNLinSolSolve(solver_, A.get(), x, rhs, 0.0), SUNLS_SUCCESS);
    double error = 0.0;
    for (int i = 0; i < n; ++i) error = std::max(error, std::abs(NV_Ith_S(x, i) - expected(i)));
    // b unchanged (CVODE reuses it)
    for (int i = 0; i < n; ++i) EXPECT_EQ(NV_Ith_S(rhs, i), b(i));
    N_VDestroy(x);
    N_VDestroy(rhs);
    return error / expected.cwiseAbs().maxCoeff();
  }

  SundialsContext context_;
  SUNLinearSolver solver_ = nullptr;
};

TEST_F(SparseLuTest, NewtonMatricesOfDrivePatternsAgreeWithDenseLu) {
  std::mt19937 rng(20261204);
  for (int trial = 0; trial < 12; ++trial) {
    const Pattern pattern = DrivePattern(20 + 15 * trial, rng);
    Csc A(pattern, context_);
    // J: random entries, each row scaled by up to 1e6 (stiff shafts next to slow inertias); a
    // row's diagonal of J is negative (damping).
    std::uniform_real_distribution<double> u(-1.0, 1.0), exponent(0.0, 6.0);
    std::vector<double> row_scale(pattern.n);
    for (double& s : row_scale) s = std::pow(10.0, exponent(rng));
    std::vector<std::vector<double>> J(pattern.n, std::vector<double>(pattern.n, 0.0));
    for (const auto& [j, i] : pattern.entries) J[i][j] = row_scale[i] * (i == j ? -std::abs(u(rng)) - 0.1 : u(rng));
    if (solver_ != nullptr) SUNLinSolFree(solver_);
    solver_ = SparseLuSolver(A.get(), context_);
    ASSERT_NE(solver_, nullptr);
    ASSERT_EQ(SUNLinSolInitialize(solver_), SUNLS_SUCCESS);
    // CVODE's sequence: gamma changes by tens of per cent between setups, over decades.
    long setups = 0;
    for (double gamma : {1e-6, 1.4e-6, 3e-5, 2e-4, 1e-3, 0.1}) {
      const Eigen::MatrixXd dense = A.Fill([&](int i, int j) { return (i == j ? 1.0 : 0.0) - gamma * J[i][j]; });
      ASSERT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_SUCCESS) << "trial " << trial << ", gamma " << gamma;
      ++setups;
      const double cond = dense.inverse().cwiseAbs().rowwise().sum().maxCoeff() * dense.cwiseAbs().rowwise().sum().maxCoeff();
      EXPECT_LT(SolveError(dense, A, rng), 1e-14 * std::max(cond, 1.0) * pattern.n)
          << "trial " << trial << ", gamma " << gamma << ", condition " << cond;
    }
    const SparseLuStatistics stats = SparseLuStats(solver_);
    EXPECT_EQ(stats.analyses, 1);
    EXPECT_EQ(stats.pivotings - stats.guard_failures + stats.refactorizations, setups);
    EXPECT_GE(stats.refactorizations, setups - 2) << "trial " << trial;  // the fixed order is reused
    EXPECT_EQ(stats.solves, setups);
    EXPECT_GT(stats.l_entries, 0);
  }
}

// Solves with SUNLinSol_KLU (AMD ordering, as the simulator configured it) and with the sparse LU
// after the same sequence of setups give the same doubles: the refactorisations replay KLU's
// arithmetic, and both pivot afresh at the same setups (CVODE's re-initialisation, a zero pivot on
// the fixed order, a large condition estimate).
TEST_F(SparseLuTest, SolutionsAreKlusBitForBit) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 6; ++trial) {
    const Pattern pattern = DrivePattern(30 + 40 * trial, rng);
    Csc A(pattern, context_);
    const int n = pattern.n;
    std::uniform_real_distribution<double> u(-1.0, 1.0), exponent(0.0, 6.0);
    std::vector<double> row_scale(n);
    for (double& s : row_scale) s = std::pow(10.0, exponent(rng));
    std::vector<std::vector<double>> J(n, std::vector<double>(n, 0.0));
    for (const auto& [j, i] : pattern.entries) J[i][j] = row_scale[i] * (i == j ? -std::abs(u(rng)) - 0.1 : u(rng));
    if (solver_ != nullptr) SUNLinSolFree(solver_);
    solver_ = SparseLuSolver(A.get(), context_);
    N_Vector y = N_VNew_Serial(n, context_);
    SUNLinearSolver klu = SUNLinSol_KLU(y, A.get(), context_);
    ASSERT_NE(klu, nullptr);
    ASSERT_EQ(SUNLinSol_KLUSetOrdering(klu, 0), SUNLS_SUCCESS);
    N_Vector b = N_VNew_Serial(n, context_), x_klu = N_VNew_Serial(n, context_), x_lu = N_VNew_Serial(n, context_);
    SUNLinSolInitialize(klu);
    SUNLinSolInitialize(solver_);
    int setups = 0, failures = 0;
    for (double gamma : {1e-6, 1.4e-6, 3e-5, 2e-4, 1e-3, 2e-2, 0.1, 0.13, 1e-4}) {
      for (int variant = 0; variant < 3; ++variant) {
        // variant 1: a zero diagonal entry of M (a pivot of the fixed order may vanish); variant
        // 2: a node's speed row a copy of its angle row (the same pattern) but for 1e-12 on the
        // diagonal, nearly singular (the condition estimate decides)
        const int special = std::uniform_int_distribution<int>(0, n - 1)(rng);
        const int angle = special - special % 2;
        auto m = [&](int i, int j) { return (i == j ? 1.0 : 0.0) - gamma * J[i][j]; };
        A.Fill([&](int i, int j) {
          if (variant == 1 && i == special && j == special) return 0.0;
          if (variant == 2 && i == angle + 1) return m(angle, j) + (j == i ? 1e-12 : 0.0);
          return m(i, j);
        });
        if (variant == 1) SUNLinSolInitialize(klu), SUNLinSolInitialize(solver_);  // as CVodeReInit
        const int flag_klu = SUNLinSolSetup(klu, A.get());
        const int flag_lu = SUNLinSolSetup(solver_, A.get());
        ++setups;
        ASSERT_EQ(flag_lu, flag_klu) << "trial " << trial << ", gamma " << gamma << ", variant " << variant;
        if (flag_klu != SUNLS_SUCCESS) {  // as the simulator did: KLU pivots afresh after a failure
          ++failures;
          ASSERT_EQ(SUNLinSol_KLUReInit(klu, A.get(), SUNSparseMatrix_NNZ(A.get()), SUNKLU_REINIT_PARTIAL), SUNLS_SUCCESS);
          continue;
        }
        for (int i = 0; i < n; ++i) NV_Ith_S(b, i) = u(rng);
        ASSERT_EQ(SUNLinSolSolve(klu, A.get(), x_klu, b, 0.0), SUNLS_SUCCESS);
        ASSERT_EQ(SUNLinSolSolve(solver_, A.get(), x_lu, b, 0.0), SUNLS_SUCCESS);
        int different = 0;
        for (int i = 0; i < n; ++i) different += std::memcmp(&NV_Ith_S(x_klu, i), &NV_Ith_S(x_lu, i), sizeof(double)) != 0;
        EXPECT_EQ(different, 0) << "trial " << trial << ", gamma " << gamma << ", variant " << variant;
      }
    }
    const SparseLuStatistics stats = SparseLuStats(solver_);
    EXPECT_GE(stats.refactorizations, setups / 3) << "trial " << trial;
    EXPECT_GE(stats.pivotings, 9) << "trial " << trial;  // at least the re-initialisations
    EXPECT_GE(stats.guard_failures, 1) << "trial " << trial;  // the nearly singular ones
    RecordProperty("failures_trial_" + std::to_string(trial), failures);
    RecordProperty("guard_trial_" + std::to_string(trial), static_cast<int>(stats.guard_failures));
    RecordProperty("pivotings_trial_" + std::to_string(trial), static_cast<int>(stats.pivotings));
    N_VDestroy(b), N_VDestroy(x_klu), N_VDestroy(x_lu), N_VDestroy(y);
    SUNLinSolFree(klu);
  }
}

// A full 3 x 3 pattern, first diagonally dominant (KLU pivots on the diagonal), then with a zero
// diagonal: the first pivot of the fixed order is zero though the matrix is not singular. As with
// SUNLinSol_KLU the setup fails recoverably, and the next one pivots afresh.
TEST_F(SparseLuTest, ZeroPivotOnTheFixedOrderFailsRecoverablyThenPivotsAfresh) {
  Pattern pattern;
  pattern.n = 3;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) pattern.entries.insert({j, i});
  Csc A(pattern, context_);
  std::mt19937 rng(7);
  solver_ = SparseLuSolver(A.get(), context_);
  ASSERT_NE(solver_, nullptr);
  SUNLinSolInitialize(solver_);
  Eigen::MatrixXd dense = A.Fill([](int i, int j) { return i == j ? 4.0 : 1.0; });
  ASSERT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_SUCCESS);
  EXPECT_LT(SolveError(dense, A, rng), 1e-15);
  dense = A.Fill([](int i, int j) { return i == j ? 0.0 : 1.0 + i; });
  EXPECT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_PACKAGE_FAIL_REC);
  ASSERT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_SUCCESS);
  EXPECT_LT(SolveError(dense, A, rng), 1e-15);
  SparseLuStatistics stats = SparseLuStats(solver_);
  EXPECT_EQ(stats.guard_failures, 1);
  EXPECT_EQ(stats.pivotings, 2);
  EXPECT_EQ(stats.refactorizations, 0);
  EXPECT_EQ(stats.analyses, 1);  // the same pattern: the ordering is kept
  // On the new order (pivots off the diagonal) a diagonally dominant matrix refactors.
  dense = A.Fill([](int i, int j) { return i == j ? 4.0 : 1.0; });
  ASSERT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_SUCCESS);
  EXPECT_LT(SolveError(dense, A, rng), 1e-15);
  stats = SparseLuStats(solver_);
  EXPECT_EQ(stats.refactorizations, 1);
  EXPECT_EQ(stats.pivotings, 2);
}

TEST_F(SparseLuTest, SingularMatrixIsARecoverableFailureThenPivotsAfresh) {
  std::mt19937 rng(11);
  const Pattern pattern = DrivePattern(10, rng);
  Csc A(pattern, context_);
  solver_ = SparseLuSolver(A.get(), context_);
  ASSERT_NE(solver_, nullptr);
  SUNLinSolInitialize(solver_);
  Eigen::MatrixXd dense = A.Fill([](int i, int j) { return i == j ? 10.0 : 0.5 / (1 + i + j); });
  ASSERT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_SUCCESS);
  // Two equal rows: singular on the fixed order and to the pivoting factorisation.
  dense = A.Fill([](int i, int j) { return i == 0 || i == 1 ? 1.0 : (i == j ? 10.0 : 0.5 / (1 + i + j)); });
  EXPECT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_PACKAGE_FAIL_REC);
  EXPECT_EQ(SUNLinSolLastFlag(solver_), SUNLS_PACKAGE_FAIL_REC);
  // no solve without factors
  N_Vector x = N_VNew_Serial(pattern.n, context_);
  N_VConst(1.0, x);
  EXPECT_NE(SUNLinSolSolve(solver_, A.get(), x, x, 0.0), SUNLS_SUCCESS);
  N_VDestroy(x);
  dense = A.Fill([](int i, int j) { return i == j ? 20.0 : 0.5 / (1 + i + j); });
  ASSERT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_SUCCESS);
  EXPECT_LT(SolveError(dense, A, rng), 1e-14);
  const SparseLuStatistics stats = SparseLuStats(solver_);
  EXPECT_EQ(stats.guard_failures, 1);
  EXPECT_GE(stats.pivotings, 2);  // the first, and after the failure
}

TEST_F(SparseLuTest, NewPatternIsAnalysedAfresh) {
  std::mt19937 rng(3);
  const Pattern first = DrivePattern(12, rng), second = DrivePattern(15, rng);
  Csc A(first, context_), B(second, context_);
  solver_ = SparseLuSolver(A.get(), context_);
  ASSERT_NE(solver_, nullptr);
  SUNLinSolInitialize(solver_);
  Eigen::MatrixXd dense = A.Fill([](int i, int j) { return i == j ? 5.0 : 1.0 / (1 + i + 2 * j); });
  ASSERT_EQ(SUNLinSolSetup(solver_, A.get()), SUNLS_SUCCESS);
  EXPECT_LT(SolveError(dense, A, rng), 1e-14);
  dense = B.Fill([](int i, int j) { return i == j ? 5.0 : 1.0 / (1 + 2 * i + j); });
  ASSERT_EQ(SUNLinSolSetup(solver_, B.get()), SUNLS_SUCCESS);
  EXPECT_LT(SolveError(dense, B, rng), 1e-14);
  EXPECT_EQ(SparseLuStats(solver_).analyses, 2);
}

TEST(SparseLu, RefusesMatricesItCannotFactor) {
  SundialsContext context;
  SUNMatrix dense = SUNDenseMatrix(3, 3, context);
  EXPECT_EQ(SparseLuSolver(dense, context), nullptr);
  SUNMatDestroy(dense);
  SUNMatrix csr = SUNSparseMatrix(3, 3, 3, CSR_MAT, context);
  EXPECT_EQ(SparseLuSolver(csr, context), nullptr);
  SUNMatDestroy(csr);
}

}  // namespace
}  // namespace highlift::sim::detail
