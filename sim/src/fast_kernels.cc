#include "fast_kernels.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

// The element-wise kernels are compiled twice, for the x86-64 baseline (SSE2: two doubles per
// instruction) and for AVX2 (four), and the loader picks the one the processor runs (GCC's
// function multiversioning). Element-wise operations give the same doubles either way (no FMA
// contraction in ISO C++ mode, no reordering); the reductions have an order of their own that
// does not depend on the clone (WSqrSum).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define HIGHLIFT_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define HIGHLIFT_VECTOR_CLONES
#endif

namespace highlift::sim::detail {
namespace {

// Vector data and length (the content of a serial N_Vector).
inline double* D(N_Vector v) { return NV_DATA_S(v); }
inline sunindextype L(N_Vector v) { return NV_LENGTH_S(v); }

// z = a*x + b*y, with the rounding of SUNDIALS' special cases a == b (a*(x + y)) and a == -b
// (a*(x - y)); multiplications by +-1 are exact, so the other special cases of nvector_serial.c
// give the same values as the general formula. Those with a coefficient 1 or -1 are written
// without its multiplication (the same doubles, a third fewer instructions): x + y is CVODE's
// predictor, q(q + 1)/2 calls per step at order q.
HIGHLIFT_VECTOR_CLONES void LinearSum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunindextype n = L(x);
  const double *xd = D(x), *yd = D(y);
  double* zd = D(z);
  if (a == 1.0 && b == 1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] + yd[i];
  } else if (a == 1.0 && b == -1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] - yd[i];
  } else if (b == 1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + yd[i];
  } else if (a == 1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] + b * yd[i];
  } else if (a == b && a != -1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] + yd[i]);
  } else if (a == -b && a != -1.0) {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * (xd[i] - yd[i]);
  } else {
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
  }
}

HIGHLIFT_VECTOR_CLONES void Const(sunrealtype c, N_Vector z) {
  double* zd = D(z);
  std::fill(zd, zd + L(z), c);
}

HIGHLIFT_VECTOR_CLONES void Prod(N_Vector x, N_Vector y, N_Vector z) {
  const sunindextype n = L(x);
  const double *xd = D(x), *yd = D(y);
  double* zd = D(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] * yd[i];
}

HIGHLIFT_VECTOR_CLONES void Div(N_Vector x, N_Vector y, N_Vector z) {
  const sunindextype n = L(x);
  const double *xd = D(x), *yd = D(y);
  double* zd = D(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] / yd[i];
}

HIGHLIFT_VECTOR_CLONES void Scale(sunrealtype c, N_Vector x, N_Vector z) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double* zd = D(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c * xd[i];
}

void Abs(N_Vector x, N_Vector z) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double* zd = D(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = std::abs(xd[i]);
}

void Inv(N_Vector x, N_Vector z) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double* zd = D(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = 1.0 / xd[i];
}

void AddConst(N_Vector x, sunrealtype b, N_Vector z) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double* zd = D(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = xd[i] + b;
}

sunrealtype DotProd(N_Vector x, N_Vector y) {
  const sunindextype n = L(x);
  const double *xd = D(x), *yd = D(y);
  double sum = 0.0;
  for (sunindextype i = 0; i < n; ++i) sum += xd[i] * yd[i];
  return sum;
}

sunrealtype MaxNorm(N_Vector x) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double m = 0.0;
  for (sunindextype i = 0; i < n; ++i) m = std::max(m, std::abs(xd[i]));
  return m;
}

// The weighted sums of squares behind CVODE's norms (about six per step: the Newton iterations'
// convergence, the local error test, the step size), in eight partial sums: element i adds to
// sum i mod 8, and the eight are added pairwise in one fixed order. A single running sum waits
// for each addition before the next (its latency, about four cycles per element); eight are
// independent, and both clones compute the same doubles (each partial sum takes its elements in
// order: SSE2 in four registers of two, AVX2 in two of four).
constexpr int kPartialSums = 8;

inline double AddPartialSums(const double* s) {
  return ((s[0] + s[4]) + (s[1] + s[5])) + ((s[2] + s[6]) + (s[3] + s[7]));
}

HIGHLIFT_VECTOR_CLONES sunrealtype WSqrSum(N_Vector x, N_Vector w) {
  const sunindextype n = L(x);
  const double *xd = D(x), *wd = D(w);
  double s[kPartialSums] = {};
  sunindextype i = 0;
  for (; i + kPartialSums <= n; i += kPartialSums)
    for (int j = 0; j < kPartialSums; ++j) {
      const double p = xd[i + j] * wd[i + j];
      s[j] += p * p;
    }
  for (int j = 0; i + j < n; ++j) {
    const double p = xd[i + j] * wd[i + j];
    s[j] += p * p;
  }
  return AddPartialSums(s);
}

HIGHLIFT_VECTOR_CLONES sunrealtype WSqrSumMask(N_Vector x, N_Vector w, N_Vector id) {
  const sunindextype n = L(x);
  const double *xd = D(x), *wd = D(w), *idd = D(id);
  double s[kPartialSums] = {};
  sunindextype i = 0;
  for (; i + kPartialSums <= n; i += kPartialSums)
    for (int j = 0; j < kPartialSums; ++j) {
      const double p = idd[i + j] > 0.0 ? xd[i + j] * wd[i + j] : 0.0;
      s[j] += p * p;
    }
  for (int j = 0; i + j < n; ++j) {
    const double p = idd[i + j] > 0.0 ? xd[i + j] * wd[i + j] : 0.0;
    s[j] += p * p;
  }
  return AddPartialSums(s);
}

sunrealtype WrmsNorm(N_Vector x, N_Vector w) { return std::sqrt(WSqrSum(x, w) / static_cast<double>(L(x))); }

sunrealtype WrmsNormMask(N_Vector x, N_Vector w, N_Vector id) {
  return std::sqrt(WSqrSumMask(x, w, id) / static_cast<double>(L(x)));
}

sunrealtype Min(N_Vector x) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double m = xd[0];
  for (sunindextype i = 1; i < n; ++i)
    if (xd[i] < m) m = xd[i];
  return m;
}

sunrealtype WL2Norm(N_Vector x, N_Vector w) { return std::sqrt(WSqrSum(x, w)); }

sunrealtype L1Norm(N_Vector x) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double sum = 0.0;
  for (sunindextype i = 0; i < n; ++i) sum += std::abs(xd[i]);
  return sum;
}

void Compare(sunrealtype c, N_Vector x, N_Vector z) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double* zd = D(z);
  for (sunindextype i = 0; i < n; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}

booleantype InvTest(N_Vector x, N_Vector z) {
  const sunindextype n = L(x);
  const double* xd = D(x);
  double* zd = D(z);
  booleantype no_zero = SUNTRUE;
  for (sunindextype i = 0; i < n; ++i) {
    if (xd[i] == 0.0) no_zero = SUNFALSE;
    else zd[i] = 1.0 / xd[i];
  }
  return no_zero;
}

booleantype ConstrMask(N_Vector c, N_Vector x, N_Vector m) {
  const sunindextype n = L(x);
  const double *cd = D(c), *xd = D(x);
  double* md = D(m);
  bool violated = false;
  for (sunindextype i = 0; i < n; ++i) {
    md[i] = 0.0;
    if (cd[i] == 0.0) continue;
    const bool test = (std::abs(cd[i]) > 1.5 && xd[i] * cd[i] <= 0.0) || (std::abs(cd[i]) > 0.5 && xd[i] * cd[i] < 0.0);
    if (test) {
      md[i] = 1.0;
      violated = true;
    }
  }
  return violated ? SUNFALSE : SUNTRUE;
}

sunrealtype MinQuotient(N_Vector num, N_Vector denom) {
  const sunindextype n = L(num);
  const double *nd = D(num), *dd = D(denom);
  bool first = true;
  double m = std::numeric_limits<double>::max();  // SUN_BIG_REAL when no denominator is non-zero
  for (sunindextype i = 0; i < n; ++i) {
    if (dd[i] == 0.0) continue;
    const double q = nd[i] / dd[i];
    m = first ? q : std::min(m, q);
    first = false;
  }
  return m;
}

// Fused operations (nvector_serial.c semantics, with its aliasing cases).
HIGHLIFT_VECTOR_CLONES int LinearCombination(int nvec, sunrealtype* c, N_Vector* X, N_Vector z) {
  if (nvec < 1) return -1;
  if (nvec == 1) {
    Scale(c[0], X[0], z);
    return 0;
  }
  if (nvec == 2) {
    LinearSum(c[0], X[0], c[1], X[1], z);
    return 0;
  }
  const sunindextype n = L(z);
  double* zd = D(z);
  if (X[0] == z && c[0] == 1.0) {
    for (int k = 1; k < nvec; ++k) {
      const double* xd = D(X[k]);
      const double ck = c[k];
      for (sunindextype i = 0; i < n; ++i) zd[i] += ck * xd[i];
    }
    return 0;
  }
  if (X[0] == z) {
    for (sunindextype i = 0; i < n; ++i) zd[i] *= c[0];
  } else {
    const double* x0 = D(X[0]);
    for (sunindextype i = 0; i < n; ++i) zd[i] = c[0] * x0[i];
  }
  for (int k = 1; k < nvec; ++k) {
    const double* xd = D(X[k]);
    const double ck = c[k];
    for (sunindextype i = 0; i < n; ++i) zd[i] += ck * xd[i];
  }
  return 0;
}

HIGHLIFT_VECTOR_CLONES int ScaleAddMulti(int nvec, sunrealtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  if (nvec < 1) return -1;
  if (nvec == 1) {
    LinearSum(a[0], x, 1.0, Y[0], Z[0]);
    return 0;
  }
  const sunindextype n = L(x);
  const double* xd = D(x);
  for (int k = 0; k < nvec; ++k) {
    const double* yd = D(Y[k]);
    double* zd = D(Z[k]);
    const double ak = a[k];
    for (sunindextype i = 0; i < n; ++i) zd[i] = ak * xd[i] + yd[i];
  }
  return 0;
}

int DotProdMulti(int nvec, N_Vector x, N_Vector* Y, sunrealtype* dotprods) {
  if (nvec < 1) return -1;
  for (int k = 0; k < nvec; ++k) dotprods[k] = DotProd(x, Y[k]);
  return 0;
}

// Sparse matrices (compressed columns).
inline sunindextype Columns(SUNMatrix A) { return SM_CONTENT_S(A)->N; }
inline sunindextype Used(SUNMatrix A) { return SM_INDEXPTRS_S(A)[SM_NP_S(A)]; }

int ZeroSparse(SUNMatrix A) {
  SUNMatrixContent_Sparse c = SM_CONTENT_S(A);
  std::memset(c->data, 0, sizeof(double) * static_cast<std::size_t>(c->NNZ));
  std::memset(c->indexvals, 0, sizeof(sunindextype) * static_cast<std::size_t>(c->NNZ));
  std::memset(c->indexptrs, 0, sizeof(sunindextype) * static_cast<std::size_t>(c->NP + 1));
  return 0;
}

// B = A when B can hold A's entries; otherwise SUNDIALS reallocates B.
int CopySparse(SUNMatrix A, SUNMatrix B) {
  SUNMatrixContent_Sparse a = SM_CONTENT_S(A), b = SM_CONTENT_S(B);
  if (a->sparsetype != CSC_MAT || b->sparsetype != CSC_MAT || a->M != b->M || a->N != b->N || b->NNZ < Used(A))
    return SUNMatCopy_Sparse(A, B);
  const sunindextype nnz = Used(A);
  std::memcpy(b->data, a->data, sizeof(double) * static_cast<std::size_t>(nnz));
  std::memcpy(b->indexvals, a->indexvals, sizeof(sunindextype) * static_cast<std::size_t>(nnz));
  std::memcpy(b->indexptrs, a->indexptrs, sizeof(sunindextype) * static_cast<std::size_t>(a->NP + 1));
  return 0;
}

// A = c*A + I when every diagonal entry is in the pattern; otherwise SUNDIALS inserts them.
// The diagonal is found by a binary search per column (the rows of a column are sorted in the
// simulator's matrices), then every entry is scaled in one loop and 1 added on the diagonal: the
// same doubles as c*a + (diagonal ? 1 : 0) per entry. A column without its diagonal, or with
// unsorted rows, hands the matrix to SUNDIALS.
int ScaleAddISparse(sunrealtype c, SUNMatrix A) {
  SUNMatrixContent_Sparse m = SM_CONTENT_S(A);
  if (m->sparsetype != CSC_MAT || m->M != m->N) return SUNMatScaleAddI_Sparse(c, A);
  const sunindextype n = Columns(A);
  const sunindextype* ptr = m->indexptrs;
  const sunindextype* row = m->indexvals;
  thread_local std::vector<sunindextype> diagonal;
  diagonal.resize(static_cast<std::size_t>(n));
  for (sunindextype j = 0; j < n; ++j) {
    const sunindextype* begin = row + ptr[j];
    const sunindextype* end = row + ptr[j + 1];
    const sunindextype* at = std::lower_bound(begin, end, j);
    if (at == end || *at != j) return SUNMatScaleAddI_Sparse(c, A);
    diagonal[static_cast<std::size_t>(j)] = at - row;
  }
  double* data = m->data;
  const sunindextype nnz = ptr[n];
  for (sunindextype k = 0; k < nnz; ++k) data[k] = c * data[k] + 0.0;
  for (sunindextype j = 0; j < n; ++j) data[diagonal[static_cast<std::size_t>(j)]] += 1.0;
  return 0;
}

// CVODE's linear solver interface keeps a copy of the Jacobian (savedJ) cloned from the
// matrix it was given; a clone of SUNDIALS' gets a fresh operation table, so the clone carries
// ours on (the copy savedJ -> A of every setup without a new Jacobian is the frequent one).
SUNMatrix CloneSparse(SUNMatrix A) {
  SUNMatrix B = SUNMatClone_Sparse(A);
  if (B) InstallFastSparseOps(B);
  return B;
}

}  // namespace

HIGHLIFT_VECTOR_CLONES void ScaleAddIdentity(std::size_t n, double scale, const double* values,
                                             const double* identity, double* out) {
  for (std::size_t p = 0; p < n; ++p) out[p] = (scale * values[p] + 0.0) + identity[p];
}

HIGHLIFT_VECTOR_CLONES bool ErrorWeights(std::size_t n, double rtol, const double* atol, bool atol_has_zero,
                                         const double* y, double* ewt) {
  // rtol * |y| + atol as N_VLinearSum(rtol, |y|, 1, atol) forms it (a * x + y, no contraction).
  if (!atol_has_zero) {
    for (std::size_t i = 0; i < n; ++i) ewt[i] = 1.0 / (rtol * std::abs(y[i]) + atol[i]);
    return true;
  }
  for (std::size_t i = 0; i < n; ++i) ewt[i] = rtol * std::abs(y[i]) + atol[i];
  if (n > 0) {  // N_VMin's scan
    double smallest = ewt[0];
    for (std::size_t i = 1; i < n; ++i)
      if (ewt[i] < smallest) smallest = ewt[i];
    if (smallest <= 0.0) return false;
  }
  for (std::size_t i = 0; i < n; ++i) ewt[i] = 1.0 / ewt[i];
  return true;
}

void InstallFastVectorOps(N_Vector v) {
  N_Vector_Ops ops = v->ops;
  ops->nvlinearsum = LinearSum;
  ops->nvconst = Const;
  ops->nvprod = Prod;
  ops->nvdiv = Div;
  ops->nvscale = Scale;
  ops->nvabs = Abs;
  ops->nvinv = Inv;
  ops->nvaddconst = AddConst;
  ops->nvdotprod = DotProd;
  ops->nvmaxnorm = MaxNorm;
  ops->nvwrmsnorm = WrmsNorm;
  ops->nvwrmsnormmask = WrmsNormMask;
  ops->nvmin = Min;
  ops->nvwl2norm = WL2Norm;
  ops->nvl1norm = L1Norm;
  ops->nvcompare = Compare;
  ops->nvinvtest = InvTest;
  ops->nvconstrmask = ConstrMask;
  ops->nvminquotient = MinQuotient;
  ops->nvlinearcombination = LinearCombination;
  ops->nvscaleaddmulti = ScaleAddMulti;
  ops->nvdotprodmulti = DotProdMulti;
  ops->nvdotprodlocal = DotProd;
  ops->nvmaxnormlocal = MaxNorm;
  ops->nvminlocal = Min;
  ops->nvl1normlocal = L1Norm;
  ops->nvinvtestlocal = InvTest;
  ops->nvconstrmasklocal = ConstrMask;
  ops->nvminquotientlocal = MinQuotient;
  ops->nvwsqrsumlocal = WSqrSum;
  ops->nvwsqrsummasklocal = WSqrSumMask;
}

void InstallFastSparseOps(SUNMatrix A) {
  A->ops->zero = ZeroSparse;
  A->ops->copy = CopySparse;
  A->ops->scaleaddi = ScaleAddISparse;
  A->ops->clone = CloneSparse;
}

}  // namespace highlift::sim::detail
