// Internal: the direct solver of CVODE's Newton systems (I - gamma*J) x = b on the Jacobian
// pattern of a network, with the states that couple to nothing but their neighbours
// eliminated before KLU factors the rest.
//
// Why: about half the states of a drive network are spring twists, der(phi_rel) = w_a - w_b.
// A twist's row of J holds only the speeds of its two nodes and its column only the nodes its
// torque accelerates, which the spring's damper couples already: eliminating it (a Schur
// complement on a diagonal block) adds no entry to the rest. KLU then factors and solves a
// system of about half the size, on about half the entries, and the eliminated states cost a
// multiply-add per entry of their rows and columns. The answer is that of the full system
// up to roundoff.
#pragma once

#include <optional>
#include <vector>

#include "sundials_compat.h"

namespace highlift::sim::detail {

/// Which states of a pattern (compressed columns, rows sorted, structurally symmetric, every
/// diagonal entry present) are eliminated. Candidates are the states with a speed row: the
/// states whose derivative depends on those states alone (a node angle on its speed, a twist on
/// the speeds of its nodes; System::SpeedRows). A candidate is eliminated when its row holds no
/// eliminated state and no entry outside the pattern, and every kept row of its column holds its
/// row's columns: eliminating it then adds no entry to the pattern of the rest.
std::vector<char> EliminatedStates(const std::vector<int>& colptr, const std::vector<int>& rows,
                                   const std::vector<std::optional<std::vector<int>>>& speed_rows);

/// A SUNLinearSolver (type direct) for the compressed-column matrix of that pattern. Its setup
/// checks that the rows of the eliminated states of M hold nothing outside their speed rows
/// and that their diagonals exceed 1e-8 of their rows' largest entries, forms the Schur
/// complement of the rest and factors it with KLU (AMD ordering, KLU's default scaling; the
/// pivot order of the last factorisation is reused while KLU's refactorisation and condition
/// estimate allow, as in SUNLinSol_KLU, and a failed refactorisation pivots afresh at once).
/// A matrix that fails the check is factored whole (counted, ReducedKluFullSetups). A failed
/// factorisation is reported as recoverable (CVODE retries with a smaller step). Returns null
/// when no state can be eliminated (then SUNLinSol_KLU is the solver to use).
SUNLinearSolver NewReducedKlu(const std::vector<int>& colptr, const std::vector<int>& rows,
                              const std::vector<std::optional<std::vector<int>>>& speed_rows, SUNContext ctx);

/// The size of the system KLU factors (the states not eliminated) of a solver from NewReducedKlu.
int ReducedKluSize(SUNLinearSolver S);
/// How many of its setups factored the whole matrix (the check above failed).
long ReducedKluFullSetups(SUNLinearSolver S);
/// The matrix of the next setup of a solver from NewReducedKlu is the Jacobian J, and the
/// solver forms M = I - gamma*J itself as it reads the entries (the same doubles as
/// SUNMatScaleAddI(-gamma, J)). CVODE's linear-system function calls it (Simulator::Run), so
/// the Jacobian stays in CVODE's matrix between its evaluations: no copy of it and no pass of
/// its own to form M at each setup. Without it a setup reads M.
void ReducedKluSetGamma(SUNLinearSolver S, double gamma);

}  // namespace highlift::sim::detail
