// The sparse LU of the simulator's Newton matrices (see sparse_lu.h for what and why).
//
// Notation (KLU's): P * (R \ A) * Q = L * U + F with P the row permutation of the pivots, Q the
// fill-reducing column order and the block triangular form, R the diagonal of row scale factors
// (the largest magnitude of each row, recomputed at every factorisation), L * U the factors of the
// diagonal blocks (L unit lower triangular), F the entries of the blocks above the diagonal. The
// factors are stored column by column in one array, each column sorted by row (U's entries above
// the diagonal, U(j, j), L's entries below it); F's entries follow, column by column in KLU's
// order. Rows of a column that follow each other are runs, which the loops take without index
// lists; the updates themselves keep KLU's order, so every entry sees the same operations.
#include "sparse_lu.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace highlift::sim::detail {
namespace {

static_assert(std::is_same_v<sunindextype, SuiteSparse_long>,
              "the sparse LU hands SUNDIALS' index arrays to KLU's long-integer interface");

struct Content {
  SparseLuOptions options;
  SparseLuStatistics stats;
  sunindextype last_flag = SUNLS_SUCCESS;

  klu_l_common common{};
  klu_l_symbolic* symbolic = nullptr;
  klu_l_numeric* numeric = nullptr;  ///< KLU's factors of the last pivoting (the condition estimate)
  bool pivot_next = true;  ///< the next setup pivots afresh (first setup, Initialize, a failure)

  // The pattern the program was compiled for.
  int n = 0;
  std::vector<sunindextype> pattern_colptr, pattern_rows;

  // The program. Offsets are into `values`: the factors' columns, then the entries of the
  // off-diagonal blocks (F) column by column.
  std::vector<int> row_of_pivot;       ///< P: the original row of pivot k
  std::vector<int> column_of_pivot;    ///< Q: the original column of pivot k
  std::vector<int> block_begin;        ///< the diagonal blocks (BTF), as pivot ranges
  std::vector<int> scatter;            ///< per entry of A (CSC order): its offset in `values`
  std::vector<int> column_begin;       ///< per column (n + 1): offset of its first entry
  std::vector<int> diagonal;           ///< per column: offset of U(j, j)
  std::vector<char> singleton;         ///< per column: a block of its own (no zero-pivot test)
  std::vector<int> offdiagonal_begin;  ///< per column (n + 1): offset of its first entry of F
  std::vector<int> row;                ///< per entry of `values`: its (permuted) row
  std::vector<int> update_begin;       ///< per column (n + 1): its range in the updates
  std::vector<int> update_multiplier;  ///< per update by column k of column j: offset of U(k, j)
  std::vector<int> update_run_begin;   ///< per update (+ 1): its range in the update runs
  /// Runs of L(:, k) with consecutive rows: the offset of the first source entry, of its target in
  /// column j (consecutive too: the columns are sorted by row and closed under the elimination),
  /// and the length.
  std::vector<int> run_source, run_target, run_length;
  /// The solves' runs of consecutive rows: per column the range of L's runs and of U's runs in
  /// (solve_offset, solve_row, solve_length).
  std::vector<int> lower_run_begin, lower_run_end, upper_run_begin, upper_run_end;
  std::vector<int> solve_offset, solve_row, solve_length;

  /// KLU's factors the program was compiled from (their patterns and permutations), and where
  /// each of their entries is in `values` (U's, then L's; -1 for L's unit diagonal).
  std::vector<sunindextype> structure;
  std::vector<int> slot;

  // The numbers.
  std::vector<double> values, row_scale, work;

  ~Content() {
    if (numeric != nullptr) klu_l_free_numeric(&numeric, &common);
    if (symbolic != nullptr) klu_l_free_symbolic(&symbolic, &common);
  }
};

Content* Get(SUNLinearSolver S) { return static_cast<Content*>(S->content); }

bool SamePattern(const Content& c, SUNMatrix A) {
  const sunindextype n = SUNSparseMatrix_Columns(A);
  if (n != c.n || static_cast<std::size_t>(n) + 1 != c.pattern_colptr.size()) return false;
  const sunindextype* colptr = SUNSparseMatrix_IndexPointers(A);
  if (std::memcmp(colptr, c.pattern_colptr.data(), (n + 1) * sizeof(sunindextype)) != 0) return false;
  return std::memcmp(SUNSparseMatrix_IndexValues(A), c.pattern_rows.data(), colptr[n] * sizeof(sunindextype)) == 0;
}

// y -= x * a over `count` entries (KLU's MULT_SUB); y and x do not overlap.
inline void SubtractScaled(double* __restrict y, const double* __restrict x, int count, double a) {
  for (int t = 0; t < count; ++t) y[t] -= x[t] * a;
}

// KLU's row scale factors (klu_scale, scale = 2): the largest magnitude of each row, 1 for a zero
// row; written as KLU's MAX so that a NaN propagates the same way.
void RowScale(Content& c, const double* a) {
  std::fill(c.row_scale.begin(), c.row_scale.end(), 0.0);
  const std::size_t nnz = c.pattern_rows.size();
  for (std::size_t p = 0; p < nnz; ++p) {
    double& r = c.row_scale[c.pattern_rows[p]];
    const double v = std::abs(a[p]);
    r = r > v ? r : v;
  }
  for (double& r : c.row_scale)
    if (r == 0.0) r = 1.0;
}

// Numeric factorisation on the compiled order, operation for operation KLU's klu_refactor (the
// same scaled entries, updates in the same order, divisions by the pivot), so the factors are
// KLU's to the bit. False at a zero pivot of a block larger than one (where KLU stops).
bool Refactor(Content& c, const double* a) {
  RowScale(c, a);
  double* f = c.values.data();
  std::fill(c.values.begin(), c.values.end(), 0.0);
  const std::size_t nnz = c.scatter.size();
  for (std::size_t p = 0; p < nnz; ++p) f[c.scatter[p]] = a[p] / c.row_scale[c.pattern_rows[p]];
  const int* multiplier = c.update_multiplier.data();
  const int* run_begin = c.update_run_begin.data();
  const int* run_source = c.run_source.data();
  const int* run_target = c.run_target.data();
  const int* run_length = c.run_length.data();
  for (int j = 0; j < c.n; ++j) {
    for (int u = c.update_begin[j]; u < c.update_begin[j + 1]; ++u) {
      const double m = f[multiplier[u]];
      for (int r = run_begin[u]; r < run_begin[u + 1]; ++r)
        SubtractScaled(f + run_target[r], f + run_source[r], run_length[r], m);
    }
    const int d = c.diagonal[j], end = c.column_begin[j + 1];
    const double pivot = f[d];
    if (pivot == 0.0 && !c.singleton[j]) return false;
    for (int k = d + 1; k < end; ++k) f[k] = f[k] / pivot;
  }
  return true;
}

// klu_rcond: the smallest over the largest magnitude of U's diagonal, 0 if one is zero or NaN.
double CheapReciprocalCondition(const Content& c) {
  double smallest = 0.0, largest = 0.0;
  for (int j = 0; j < c.n; ++j) {
    const double u = std::abs(c.values[c.diagonal[j]]);
    if (std::isnan(u) || u == 0.0) return 0.0;
    if (j == 0) {
      smallest = largest = u;
    } else {
      smallest = std::min(smallest, u);
      largest = std::max(largest, u);
    }
  }
  const double r = c.n > 0 ? smallest / largest : 1.0;
  return std::isnan(r) ? 0.0 : r;  // umin or umax infinite
}

// Compiles the program from KLU's factors (c.numeric) and loads their values. False if KLU's
// factors cannot be read or do not have the structure the program assumes.
bool Compile(Content& c, SUNMatrix A) {
  const sunindextype* colptr = SUNSparseMatrix_IndexPointers(A);
  const sunindextype* rows = SUNSparseMatrix_IndexValues(A);
  const int N = c.n;
  const klu_l_numeric& numeric = *c.numeric;
  const sunindextype lnz = numeric.lnz, unz = numeric.unz, nzoff = c.symbolic->nzoff;
  const sunindextype nblocks = c.symbolic->nblocks;
  std::vector<sunindextype> Lp(N + 1), Li(lnz), Up(N + 1), Ui(unz), Fp(N + 1), Fi(std::max<sunindextype>(nzoff, 1)),
      P(N), Q(N), R(nblocks + 1);
  std::vector<double> Lx(lnz), Ux(unz), Fx(std::max<sunindextype>(nzoff, 1));
  if (!klu_l_extract(c.numeric, c.symbolic, Lp.data(), Li.data(), Lx.data(), Up.data(), Ui.data(), Ux.data(),
                     Fp.data(), Fi.data(), Fx.data(), P.data(), Q.data(), nullptr, R.data(), &c.common))
    return false;
  // The same order and pattern as the program's (pivoting afresh after CVODE's re-initialisation
  // mostly finds the pivots it had): load the values alone.
  std::vector<sunindextype> structure;
  structure.reserve(Lp.size() + Li.size() + Up.size() + Ui.size() + Fp.size() + Fi.size() + P.size() + Q.size() +
                    R.size());
  for (const auto* part : {&Lp, &Li, &Up, &Ui, &Fp, &Fi, &P, &Q, &R}) structure.insert(structure.end(), part->begin(), part->end());
  if (structure == c.structure) {
    for (sunindextype p = 0; p < unz; ++p) c.values[c.slot[p]] = Ux[p];
    for (sunindextype p = 0; p < lnz; ++p)
      if (c.slot[unz + p] >= 0) c.values[c.slot[unz + p]] = Lx[p];
    for (sunindextype p = 0; p < nzoff; ++p) c.values[c.offdiagonal_begin[0] + p] = Fx[p];
    return true;
  }
  c.structure.clear();  // until the program is complete
  c.slot.assign(unz + lnz, -1);
  std::vector<int> pivot_of_row(N);
  c.row_of_pivot.assign(N, 0);
  c.column_of_pivot.assign(N, 0);
  for (int k = 0; k < N; ++k) {
    c.row_of_pivot[k] = static_cast<int>(P[k]);
    c.column_of_pivot[k] = static_cast<int>(Q[k]);
    pivot_of_row[P[k]] = k;
  }
  c.block_begin.assign(R.begin(), R.end());
  const int factor_entries = static_cast<int>(lnz - N + unz);
  c.values.assign(factor_entries + nzoff, 0.0);
  c.row.assign(factor_entries + nzoff, 0);
  c.column_begin.assign(N + 1, 0);
  c.diagonal.assign(N, 0);
  c.singleton.assign(N, 0);
  c.offdiagonal_begin.assign(N + 1, factor_entries);
  c.scatter.assign(colptr[N], 0);
  c.update_begin.assign(N + 1, 0);
  c.update_multiplier.clear();
  c.update_run_begin.assign(1, 0);
  c.run_source.clear();
  c.run_target.clear();
  c.run_length.clear();
  std::vector<int> stamp(N, -1), position(N, 0);
  std::vector<std::pair<sunindextype, sunindextype>> column_entries;
  int next = 0;
  long l_entries = 0, u_entries = 0;
  for (sunindextype b = 0; b < nblocks; ++b) {
    const int k1 = static_cast<int>(R[b]), k2 = static_cast<int>(R[b + 1]);
    for (int j = k1; j < k2; ++j) {
      c.singleton[j] = k2 - k1 == 1;
      c.column_begin[j] = next;
      // U(:, j) in KLU's order, its diagonal last; then L(:, j) after its unit diagonal.
      if (Up[j + 1] - Up[j] < 1 || Ui[Up[j + 1] - 1] != j || Li[Lp[j]] != j) return false;
      column_entries.clear();  // (row, index into Ux, or unz + index into Lx)
      for (sunindextype p = Up[j]; p < Up[j + 1] - 1; ++p) {
        if (Ui[p] >= j) return false;
        column_entries.emplace_back(Ui[p], p);
      }
      column_entries.emplace_back(j, Up[j + 1] - 1);
      for (sunindextype p = Lp[j] + 1; p < Lp[j + 1]; ++p) {
        if (Li[p] <= j) return false;
        column_entries.emplace_back(Li[p], unz + p);
      }
      std::sort(column_entries.begin(), column_entries.end());
      for (const auto& [i, code] : column_entries) {
        if (i < k1 || i >= k2 || stamp[i] == j) return false;
        stamp[i] = j;
        position[i] = next;
        c.row[next] = static_cast<int>(i);
        c.slot[code] = next;
        c.values[next++] = code < unz ? Ux[code] : Lx[code - unz];
      }
      c.diagonal[j] = position[j];
      u_entries += c.diagonal[j] - c.column_begin[j];
      l_entries += next - c.diagonal[j] - 1;
      // The entries of A: into the block, or (rows of earlier blocks) into F in KLU's order.
      const int column = c.column_of_pivot[j];
      sunindextype off = Fp[j];
      for (sunindextype p = colptr[column]; p < colptr[column + 1]; ++p) {
        const int i = pivot_of_row[rows[p]];
        if (i < k1 && off < nzoff) {
          if (off >= Fp[j + 1] || Fi[off] != i) return false;
          c.scatter[p] = factor_entries + static_cast<int>(off++);
        } else {
          if (stamp[i] != j) return false;
          c.scatter[p] = position[i];
        }
      }
      if (off != Fp[j + 1]) return false;
      // The updates by the columns k of U(:, j), in KLU's order.
      for (sunindextype p = Up[j]; p < Up[j + 1] - 1; ++p) {
        const int k = static_cast<int>(Ui[p]);
        const int source = c.diagonal[k] + 1, source_end = c.column_begin[k + 1];
        if (source == source_end) continue;
        c.update_multiplier.push_back(position[k]);
        for (int s = source; s < source_end; ++s) {
          const int i = c.row[s];
          if (stamp[i] != j) return false;
          if (s > source && i == c.row[s - 1] + 1 && position[i] == position[i - 1] + 1) {
            ++c.run_length.back();
          } else {
            c.run_source.push_back(s);
            c.run_target.push_back(position[i]);
            c.run_length.push_back(1);
          }
        }
        c.update_run_begin.push_back(static_cast<int>(c.run_length.size()));
      }
      c.update_begin[j + 1] = static_cast<int>(c.update_multiplier.size());
      c.column_begin[j + 1] = next;
    }
  }
  if (next != factor_entries) return false;
  // The solves' runs.
  c.lower_run_begin.assign(N, 0);
  c.lower_run_end.assign(N, 0);
  c.upper_run_begin.assign(N, 0);
  c.upper_run_end.assign(N, 0);
  c.solve_offset.clear();
  c.solve_row.clear();
  c.solve_length.clear();
  auto runs = [&](int begin, int end) {
    for (int k = begin; k < end; ++k) {
      if (k > begin && c.row[k] == c.row[k - 1] + 1) {
        ++c.solve_length.back();
      } else {
        c.solve_offset.push_back(k);
        c.solve_row.push_back(c.row[k]);
        c.solve_length.push_back(1);
      }
    }
    return static_cast<int>(c.solve_length.size());
  };
  for (int j = 0; j < N; ++j) {
    c.lower_run_begin[j] = static_cast<int>(c.solve_length.size());
    c.lower_run_end[j] = runs(c.diagonal[j] + 1, c.column_begin[j + 1]);
    c.upper_run_begin[j] = c.lower_run_end[j];
    c.upper_run_end[j] = runs(c.column_begin[j], c.diagonal[j]);
  }
  for (int j = 0; j <= N; ++j) c.offdiagonal_begin[j] = factor_entries + static_cast<int>(Fp[j]);
  for (sunindextype p = 0; p < nzoff; ++p) {
    c.row[factor_entries + p] = static_cast<int>(Fi[p]);
    c.values[factor_entries + p] = Fx[p];
  }
  c.work.assign(N, 0.0);
  c.row_scale.assign(N, 1.0);
  c.structure = std::move(structure);
  c.stats.l_entries = l_entries;
  c.stats.u_entries = u_entries;
  return true;
}

// A fresh factorisation by KLU (pivoting; the ordering is kept while the pattern is), then the
// program for its order. False if KLU finds the matrix singular or fails.
bool Pivot(Content& c, SUNMatrix A) {
  const sunindextype n = SUNSparseMatrix_Columns(A);
  sunindextype* colptr = SUNSparseMatrix_IndexPointers(A);
  sunindextype* rows = SUNSparseMatrix_IndexValues(A);
  double* values = SUNSparseMatrix_Data(A);
  ++c.stats.pivotings;
  if (c.numeric != nullptr) klu_l_free_numeric(&c.numeric, &c.common);
  if (c.symbolic == nullptr || !SamePattern(c, A)) {
    if (c.symbolic != nullptr) klu_l_free_symbolic(&c.symbolic, &c.common);
    c.n = static_cast<int>(n);
    c.pattern_colptr.assign(colptr, colptr + n + 1);
    c.pattern_rows.assign(rows, rows + colptr[n]);
    c.symbolic = klu_l_analyze(n, colptr, rows, &c.common);
    if (c.symbolic == nullptr) return false;
    ++c.stats.analyses;
  }
  c.numeric = klu_l_factor(colptr, rows, values, c.symbolic, &c.common);
  if (c.numeric == nullptr) return false;
  if (c.common.status != KLU_OK || !Compile(c, A)) {  // KLU_SINGULAR: KLU stopped at a zero pivot
    klu_l_free_numeric(&c.numeric, &c.common);
    return false;
  }
  RowScale(c, values);
  return true;
}

SUNLinearSolver_Type GetType(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID GetId(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }

int Initialize(SUNLinearSolver S) {
  // As SUNLinSol_KLU: CVODE initialises at the start and after every re-initialisation, where
  // the matrix may differ most; the fill-reducing ordering is kept while the pattern is.
  Get(S)->pivot_next = true;
  return static_cast<int>(Get(S)->last_flag = SUNLS_SUCCESS);
}

int Setup(SUNLinearSolver S, SUNMatrix A) {
  Content& c = *Get(S);
  sunindextype* colptr = SUNSparseMatrix_IndexPointers(A);
  sunindextype* rows = SUNSparseMatrix_IndexValues(A);
  double* a = SUNSparseMatrix_Data(A);
  if (c.pivot_next || !SamePattern(c, A)) {
    c.pivot_next = true;
    if (!Pivot(c, A)) return static_cast<int>(c.last_flag = SUNLS_PACKAGE_FAIL_REC);
    c.pivot_next = false;
    return static_cast<int>(c.last_flag = SUNLS_SUCCESS);
  }
  if (!Refactor(c, a)) {
    ++c.stats.guard_failures;
    c.pivot_next = true;
    return static_cast<int>(c.last_flag = SUNLS_PACKAGE_FAIL_REC);
  }
  ++c.stats.refactorizations;
  // SUNLinSol_KLU's guard: when the cheap estimate of the reciprocal condition number falls below
  // the unit roundoff to the power 2/3, KLU's condition estimate on these factors decides whether
  // to pivot afresh (rare: KLU itself refactors for the estimate).
  const double limit = std::pow(std::numeric_limits<double>::epsilon(), 2.0 / 3.0);
  if (CheapReciprocalCondition(c) < limit) {
    if (!klu_l_refactor(colptr, rows, a, c.symbolic, c.numeric, &c.common) ||
        !klu_l_condest(colptr, a, c.symbolic, c.numeric, &c.common))
      return static_cast<int>(c.last_flag = SUNLS_PACKAGE_FAIL_REC);
    if (c.common.condest > 1.0 / limit) {
      ++c.stats.guard_failures;
      c.pivot_next = true;
      if (!Pivot(c, A)) return static_cast<int>(c.last_flag = SUNLS_PACKAGE_FAIL_REC);
      c.pivot_next = false;
    }
  }
  return static_cast<int>(c.last_flag = SUNLS_SUCCESS);
}

// klu_solve's operations in its order: X = P (R \ b); per block from the last, L then U, then the
// block's columns of F; x = Q X.
int Solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, sunrealtype) {
  Content& c = *Get(S);
  if (c.pivot_next) return static_cast<int>(c.last_flag = SUNLS_PACKAGE_FAIL_UNREC);  // no factors
  const double* bv = N_VGetArrayPointer(b);
  double* xv = N_VGetArrayPointer(x);
  double* w = c.work.data();
  const double* f = c.values.data();
  const int* row = c.row.data();
  const int* run_offset = c.solve_offset.data();
  const int* run_row = c.solve_row.data();
  const int* run_length = c.solve_length.data();
  const int n = c.n;
  for (int k = 0; k < n; ++k) {
    const int i = c.row_of_pivot[k];
    w[k] = bv[i] / c.row_scale[i];
  }
  for (int block = static_cast<int>(c.block_begin.size()) - 2; block >= 0; --block) {
    const int k1 = c.block_begin[block], k2 = c.block_begin[block + 1];
    for (int j = k1; j < k2; ++j) {  // L y = w
      const double wj = w[j];
      for (int r = c.lower_run_begin[j]; r < c.lower_run_end[j]; ++r)
        SubtractScaled(w + run_row[r], f + run_offset[r], run_length[r], wj);
    }
    for (int j = k2 - 1; j >= k1; --j) {  // U z = y
      const double wj = w[j] / f[c.diagonal[j]];
      w[j] = wj;
      for (int r = c.upper_run_begin[j]; r < c.upper_run_end[j]; ++r)
        SubtractScaled(w + run_row[r], f + run_offset[r], run_length[r], wj);
    }
    if (block > 0)
      for (int j = k1; j < k2; ++j) {
        const double wj = w[j];
        for (int k = c.offdiagonal_begin[j]; k < c.offdiagonal_begin[j + 1]; ++k) w[row[k]] -= f[k] * wj;
      }
  }
  for (int k = 0; k < n; ++k) xv[c.column_of_pivot[k]] = w[k];
  ++c.stats.solves;
  return static_cast<int>(c.last_flag = SUNLS_SUCCESS);
}

sunindextype LastFlag(SUNLinearSolver S) { return Get(S)->last_flag; }

int Space(SUNLinearSolver S, long* real_words, long* integer_words) {
  const Content& c = *Get(S);
  *real_words = static_cast<long>(c.values.size() + c.row_scale.size() + c.work.size());
  *integer_words = static_cast<long>(
      c.pattern_colptr.size() + c.pattern_rows.size() + c.row_of_pivot.size() + c.column_of_pivot.size() +
      c.block_begin.size() + c.scatter.size() + c.column_begin.size() + c.diagonal.size() + c.singleton.size() +
      c.offdiagonal_begin.size() + c.row.size() + c.update_begin.size() + c.update_multiplier.size() +
      c.structure.size() + c.slot.size() + c.update_run_begin.size() + c.run_source.size() + c.run_target.size() + c.run_length.size() +
      4 * c.lower_run_begin.size() + c.solve_offset.size() + c.solve_row.size() + c.solve_length.size());
  return SUNLS_SUCCESS;
}

int Free(SUNLinearSolver S) {
  if (S == nullptr) return SUNLS_SUCCESS;
  delete Get(S);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver SparseLuSolver(SUNMatrix A, SUNContext context, const SparseLuOptions& options) {
  if (A == nullptr || SUNMatGetID(A) != SUNMATRIX_SPARSE || SUNSparseMatrix_SparseType(A) != CSC_MAT ||
      SUNSparseMatrix_Rows(A) != SUNSparseMatrix_Columns(A))
    return nullptr;
  SUNLinearSolver S = SUNLinSolNewEmpty(context);
  if (S == nullptr) return nullptr;
  auto* c = new (std::nothrow) Content;
  if (c == nullptr) {
    SUNLinSolFreeEmpty(S);
    return nullptr;
  }
  c->options = options;
  klu_l_defaults(&c->common);
  // AMD rather than KLU's default COLAMD: the pattern is structurally symmetric (the node groups'
  // cliques), where AMD gives less fill (docs/performance.md).
  c->common.ordering = 0;
  c->common.tol = options.pivot_tolerance;
  S->content = c;
  S->ops->gettype = GetType;
  S->ops->getid = GetId;
  S->ops->initialize = Initialize;
  S->ops->setup = Setup;
  S->ops->solve = Solve;
  S->ops->lastflag = LastFlag;
  S->ops->space = Space;
  S->ops->free = Free;
  return S;
}

SparseLuStatistics SparseLuStats(SUNLinearSolver S) { return Get(S)->stats; }

}  // namespace highlift::sim::detail
