// Internal: the sparse direct linear solver of the simulator's Newton matrices (M = I - gamma J
// on the network's Jacobian pattern), a SUNLinearSolver that CVODE calls like SUNLinSol_KLU.
//
// Why: CVODE refactors M after every new Jacobian and after every change of gamma by more than
// 30 % (664 of the 777 refactorisations of the A380-class jam_l3), and solves with it at every
// Newton iteration. KLU's factors of these matrices have no fill (AMD ordering); a program
// compiled once for their pattern saves KLU's per-entry index work: 3 to 5 % of the A380-class
// runs' instructions, the same doubles (docs/performance.md, issue 30, fourth pass).
//
// How: KLU does what needs a search (the fill-reducing ordering, the block triangular form, the
// threshold partial pivoting) as SUNLinSol_KLU does: at the first setup, after CVODE's
// (re-)initialisation and after a failure. From its factors the pattern of L, U and the
// off-diagonal blocks is compiled once into a flat elimination program: for each matrix entry its
// offset in the factors, for each update of column j by an earlier column k the offsets of the
// targets in column j (no searches, no scatter vector). Every other setup refactors on that fixed
// order with KLU's arithmetic operation for operation (the same row scaling, updates in the same
// order, divisions by the pivot), so the factors and solutions are KLU's to the bit, and with
// SUNLinSol_KLU's guards: a zero pivot gives SUNLS_PACKAGE_FAIL_REC (the next setup pivots
// afresh); a cheap reciprocal condition estimate (smallest over largest pivot magnitude) below
// the unit roundoff to the power 2/3 asks KLU's condition estimate, and above its inverse KLU
// pivots afresh in the same setup.
#pragma once

#include "sundials_compat.h"

namespace highlift::sim::detail {

struct SparseLuOptions {
  /// Threshold of KLU's partial pivoting (KLU's `tol`): KLU keeps the diagonal as the pivot of a
  /// column unless it is smaller than this times the largest scaled candidate. Dimensionless, in
  /// (0, 1]; KLU's default.
  double pivot_tolerance = 1e-3;
};

/// What the solver did (for tests and the performance notes).
struct SparseLuStatistics {
  long pivotings = 0;         ///< pivoting factorisations (KLU), the first one included
  long analyses = 0;          ///< fill-reducing orderings (KLU's analysis: a new pattern)
  long refactorizations = 0;  ///< numeric refactorisations on the fixed order (a zero pivot excluded)
  long guard_failures = 0;    ///< refactorisations with a zero pivot or a large condition estimate
  long solves = 0;
  long l_entries = 0, u_entries = 0;  ///< below and above the diagonal of the blocks, current order
};

/// A solver for square compressed-sparse-column matrices of the pattern of A (a later setup with
/// another pattern analyses it afresh). Returns nullptr if the matrix is not CSC or square.
SUNLinearSolver SparseLuSolver(SUNMatrix A, SUNContext context, const SparseLuOptions& options = {});

/// The statistics of a solver made by SparseLuSolver.
SparseLuStatistics SparseLuStats(SUNLinearSolver S);

}  // namespace highlift::sim::detail
