// Internal: our own implementations of the serial N_Vector operations and of the sparse
// SUNMatrix operations CVODE calls at every step, installed into the operation tables of the
// vectors and matrices the simulator creates.
//
// Why: Debian's SUNDIALS 6.4 packages are built without optimisation (the vector kernels keep
// every loop variable on the stack, nothing is vectorised). On the drive-system models a third
// of the run time went into N_VLinearSum, N_VWSqrSumLocal and the sparse matrix copy, zero and
// scale-add. These kernels have the same semantics as nvector_serial.c and sunmatrix_sparse.c
// of SUNDIALS 6.4 (operation by operation, including the special values of N_VMinQuotient and
// N_VInvTest), but for the weighted sums of squares behind CVODE's norms, which add in eight
// partial sums instead of one running sum (other roundoff, a fifth of the time); they are
// compiled with the project's optimisation. Clones inherit the tables, so
// every vector CVODE clones from the state vector uses them.
#pragma once

#include <cstddef>

#include "sundials_compat.h"

namespace highlift::sim::detail {

/// Replaces the operations of a serial vector (N_VNew_Serial) by ours.
void InstallFastVectorOps(N_Vector v);

/// Replaces zero, copy and scale-add-identity of a compressed-sparse-column matrix whose
/// pattern holds every diagonal entry (the simulator's Jacobian pattern does); the other
/// operations stay SUNDIALS'.
void InstallFastSparseOps(SUNMatrix A);

/// out = scale * values + 0.0 + identity, entry by entry (n entries): M = I - gamma*J as
/// SUNMatScaleAddI(-gamma, J) forms it, with `identity` 1 at the diagonal's positions and 0
/// elsewhere. The same doubles as the scalar loop.
void ScaleAddIdentity(std::size_t n, double scale, const double* values, const double* identity, double* out);

/// CVODE's error weights ewt_i = 1 / (rtol |y_i| + atol_i) for a vector of absolute tolerances
/// (cvEwtSetSV: N_VAbs, N_VLinearSum, N_VInv, each a pass over the states at every step) in one
/// pass, the same doubles. As CVODE when some atol_i is 0 (`atol_has_zero`): false, with ewt
/// undefined, when the smallest rtol |y_i| + atol_i is not positive.
bool ErrorWeights(std::size_t n, double rtol, const double* atol, bool atol_has_zero, const double* y, double* ewt);

}  // namespace highlift::sim::detail
