#include "reduced_klu.h"

#include <klu.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "fast_kernels.h"

namespace highlift::sim::detail {

std::vector<char> EliminatedStates(const std::vector<int>& colptr, const std::vector<int>& rows,
                                   const std::vector<std::optional<std::vector<int>>>& speed_rows) {
  const int n = static_cast<int>(colptr.size()) - 1;
  std::vector<char> eliminated(n, 0), mark(n, 0);
  for (int k = 0; k < n; ++k) eliminated[k] = speed_rows[k].has_value() ? 1 : 0;
  // Dropping a state makes its rows kept ones, which may break the test of another: repeat
  // until nothing changes (each pass only drops).
  for (bool changed = true; changed;) {
    changed = false;
    for (int k = 0; k < n; ++k) {
      if (!eliminated[k]) continue;
      const std::vector<int>& row = *speed_rows[k];
      bool ok = true;
      for (int v : row)
        if (v < 0 || v >= n || v == k || eliminated[v]) ok = false;
      // k's row lies in the pattern, and every kept row v1 of column k holds the columns of
      // k's row (the pattern is symmetric: column v1 is row v1), so M(v1, k) M(k, v2) lands on
      // an entry of the pattern.
      for (int p = colptr[k]; p < colptr[k + 1] && ok; ++p) {
        const int v1 = rows[p];
        if (v1 != k && eliminated[v1]) continue;
        for (int q = colptr[v1]; q < colptr[v1 + 1]; ++q) mark[rows[q]] = 1;
        for (int v2 : row)
          if (!mark[v2]) ok = false;
        for (int q = colptr[v1]; q < colptr[v1 + 1]; ++q) mark[rows[q]] = 0;
      }
      if (!ok) {
        eliminated[k] = 0;
        changed = true;
      }
    }
  }
  return eliminated;
}

namespace {

/// One eliminated state k: its diagonal and the entries of its column M(v, k) (v kept) and of
/// its row M(k, v) (v in its speed row), as positions in M's values and reduced indices.
struct Eliminated {
  long diagonal = 0;                      ///< position of M(k, k)
  std::vector<long> column_pos, row_pos;  ///< positions of M(v, k) and M(k, v)
  std::vector<int> column_v;              ///< the reduced index of each v of the column
  std::vector<long> zero_pos;             ///< the rest of row k in the pattern: must be 0
};

/// Position of `row` among the entries [begin, end) of `rows` (one column, rows sorted), -1 when
/// it is not there.
template <class Index>
long Find(const std::vector<Index>& rows, long begin, long end, long row) {
  const auto first = rows.begin() + begin, last = rows.begin() + end;
  const auto it = std::lower_bound(first, last, static_cast<Index>(row));
  return it != last && *it == row ? static_cast<long>(it - rows.begin()) : -1;
}

/// KLU's objects for one matrix (the reduced one, or the full one after a failed check).
struct Factors {
  std::vector<SuiteSparse_long> colptr, rows;
  std::vector<double> values;
  klu_l_symbolic* symbolic = nullptr;
  klu_l_numeric* numeric = nullptr;
  bool first = true;  ///< the next setup pivots afresh
};

struct Content {
  int n = 0, m = 0;       ///< full and reduced size
  std::vector<int> kept;  ///< full index of each reduced one
  std::vector<Eliminated> eliminated;
  /// Every eliminated state's zero_pos, in one array.
  std::vector<long> zero_positions;
  std::vector<long> s_from;  ///< position in M of each entry of the reduced matrix S
  /// S(v1, v2) -= M(v1, k) M(k, v2) / M(k, k): for eliminated state e, column entry i and row
  /// entry j, the position of S(v1, v2) is update_s[update_begin[e] + i * rows + j].
  std::vector<long> update_s, update_begin;
  std::vector<double> inverse_diagonal, row_values, z;
  /// The eliminated states' rows, flat for the solves: entries row_begin[e] .. row_begin[e + 1]
  /// of row_values (M(k, v)) and row_reduced (v's reduced index); the state of each.
  std::vector<long> row_begin;
  std::vector<int> row_reduced, eliminated_state;
  /// The eliminated states by the length of their rows (1, 2, more), for the back substitution:
  /// most rows hold one speed or two, and a loop per length has no inner loop to run. The order
  /// of the states does not matter there (each writes its own x_k from z).
  std::vector<int> rows_of_one, rows_of_two, rows_of_more;
  /// The column entries of the last setup that are not 0 (most of a pattern column is: an angle
  /// drives nothing but the elements that read it): reduced index, value and eliminated state,
  /// in the order of the states (so each z_v takes its terms in that order), n_active of them;
  /// sized for every entry of the pattern's columns.
  std::vector<int> active_v, active_e;
  std::vector<double> active_values;
  long n_active = 0;
  /// b_k / M(k, k) of each eliminated state, in a solve.
  std::vector<double> xk;
  Factors reduced, full;
  /// 1 at the diagonal's position in M's values, 0 elsewhere: M = -gamma*J + I entry by entry.
  std::vector<double> identity;
  /// M's values when the setup is given J, formed in one vectorised pass (ScaleAddIdentity) and
  /// read where the setup needs them.
  std::vector<double> m_values;
  /// The next setup is given J (ReducedKluSetGamma) rather than M.
  bool given_jacobian = false;
  double gamma = 0.0;
  bool use_full = false;  ///< the last setup factored the full matrix
  long full_setups = 0;
  klu_l_common common;
  int last_flag = 0;
};

Content* Get(SUNLinearSolver S) { return static_cast<Content*>(S->content); }

SUNLinearSolver_Type GetType(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID GetId(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }

int Initialize(SUNLinearSolver S) {
  Get(S)->reduced.first = true;
  Get(S)->full.first = true;
  Get(S)->last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

/// Factors f.values: KLU's refactorisation on the pivot order of the last factorisation
/// while it succeeds and the condition estimate allows (SUNLinSol_KLU's test), else afresh.
bool Factor(Factors& f, SuiteSparse_long size, klu_l_common& common) {
  if (f.symbolic == nullptr) {
    f.symbolic = klu_l_analyze(size, f.colptr.data(), f.rows.data(), &common);
    if (f.symbolic == nullptr) return false;
    f.first = true;
  }
  if (!f.first &&
      klu_l_refactor(f.colptr.data(), f.rows.data(), f.values.data(), f.symbolic, f.numeric, &common) != 0) {
    const double uround_twothirds = std::pow(std::numeric_limits<double>::epsilon(), 2.0 / 3.0);
    bool fresh = klu_l_rcond(f.symbolic, f.numeric, &common) == 0;
    if (!fresh && common.rcond < uround_twothirds)
      fresh = klu_l_condest(f.colptr.data(), f.values.data(), f.symbolic, f.numeric, &common) == 0 ||
              common.condest > 1.0 / uround_twothirds;
    if (!fresh) return true;
  }
  if (f.numeric != nullptr) klu_l_free_numeric(&f.numeric, &common);
  f.numeric = klu_l_factor(f.colptr.data(), f.rows.data(), f.values.data(), f.symbolic, &common);
  f.first = f.numeric == nullptr;
  return f.numeric != nullptr;
}

/// The setup on M's values as `m(p)` gives them (p: a position in the compressed columns).
template <class Entry>
int SetupOn(Content& c, const Entry& m) {
  // The eliminated rows hold nothing but their speeds, and their diagonals are not small.
  // (The zeros of all rows first, in one loop over their positions.)
  bool reducible = std::all_of(c.zero_positions.begin(), c.zero_positions.end(), [&](long p) { return m(p) == 0.0; });
  for (std::size_t e = 0; e < c.eliminated.size() && reducible; ++e) {
    const Eliminated& el = c.eliminated[e];
    double largest = 0.0;
    for (long p : el.row_pos) largest = std::max(largest, std::abs(m(p)));
    const double d = m(el.diagonal);
    if (!(std::abs(d) > 1e-8 * largest) || !std::isfinite(d)) {
      reducible = false;
      break;
    }
    c.inverse_diagonal[e] = 1.0 / d;
    for (std::size_t i = 0; i < el.row_pos.size(); ++i) c.row_values[c.row_begin[e] + i] = m(el.row_pos[i]);
  }
  c.use_full = !reducible;
  bool ok = false;
  if (reducible) {
    double* sv = c.reduced.values.data();
    for (std::size_t i = 0; i < c.s_from.size(); ++i) sv[i] = m(c.s_from[i]);
    long n_active = 0;
    int* const active_v = c.active_v.data();
    int* const active_e = c.active_e.data();
    double* const active_values = c.active_values.data();
    for (std::size_t e = 0; e < c.eliminated.size(); ++e) {
      const Eliminated& el = c.eliminated[e];
      const std::size_t n_row = el.row_pos.size();
      const double* row = c.row_values.data() + c.row_begin[e];
      const long* s_pos = c.update_s.data() + c.update_begin[e];
      for (std::size_t i = 0; i < el.column_pos.size(); ++i) {
        const double a = m(el.column_pos[i]);
        if (a == 0.0) continue;
        active_v[n_active] = el.column_v[i];
        active_e[n_active] = static_cast<int>(e);
        active_values[n_active] = a;
        ++n_active;
        const double f = a * c.inverse_diagonal[e];
        for (std::size_t j = 0; j < n_row; ++j) sv[s_pos[i * n_row + j]] -= f * row[j];
      }
    }
    c.n_active = n_active;
    ok = Factor(c.reduced, c.m, c.common);
  } else {
    ++c.full_setups;
    for (std::size_t p = 0; p < c.full.values.size(); ++p) c.full.values[p] = m(static_cast<long>(p));
    ok = Factor(c.full, c.n, c.common);
  }
  c.last_flag = ok ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
  return c.last_flag;
}

int Setup(SUNLinearSolver S, SUNMatrix A) {
  Content& c = *Get(S);
  const double* values = SUNSparseMatrix_Data(A);
  if (!c.given_jacobian) return SetupOn(c, [values](long p) { return values[p]; });
  c.given_jacobian = false;
  // M = I - gamma*J as SUNMatScaleAddI(-gamma, J) forms it (fast_kernels.cc): -gamma*J + 0.0,
  // then 1 added on the diagonal. The same doubles, formed in one pass before the setup reads them.
  ScaleAddIdentity(c.m_values.size(), -c.gamma, values, c.identity.data(), c.m_values.data());
  const double* m_values = c.m_values.data();
  return SetupOn(c, [m_values](long p) { return m_values[p]; });
}

int Solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, sunrealtype) {
  Content& c = *Get(S);
  const double* bv = N_VGetArrayPointer(b);
  double* xv = N_VGetArrayPointer(x);
  if (c.use_full) {
    if (xv != bv) std::copy(bv, bv + c.n, xv);
    const bool ok = klu_l_solve(c.full.symbolic, c.full.numeric, c.n, 1, xv, &c.common) != 0;
    c.last_flag = ok ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
    return c.last_flag;
  }
  // z = b_V - M(V, k) b_k / M(k, k): each z_v takes its terms in the order of the states.
  const std::size_t n_eliminated = c.eliminated_state.size();
  const int* const state = c.eliminated_state.data();
  const double* const inverse_diagonal = c.inverse_diagonal.data();
  double* const xk = c.xk.data();
  double* const z = c.z.data();
  for (std::size_t e = 0; e < n_eliminated; ++e) xk[e] = bv[state[e]] * inverse_diagonal[e];
  for (int r = 0; r < c.m; ++r) z[r] = bv[c.kept[r]];
  {
    const int* const v = c.active_v.data();
    const int* const of = c.active_e.data();
    const double* const a = c.active_values.data();
    for (long i = 0; i < c.n_active; ++i) z[v[i]] -= a[i] * xk[of[i]];
  }
  if (klu_l_solve(c.reduced.symbolic, c.reduced.numeric, c.m, 1, z, &c.common) == 0) {
    c.last_flag = SUNLS_PACKAGE_FAIL_REC;
    return c.last_flag;
  }
  // x_V = z; x_k = (b_k - M(k, V) x_V) / M(k, k), written after b_k was read (b may be x), by
  // rows of one entry, of two, and the rest: the same sums, term by term.
  const long* const begin = c.row_begin.data();
  const double* const row = c.row_values.data();
  const int* const v = c.row_reduced.data();
  for (const int e : c.rows_of_one) {
    const long p = begin[e];
    const int k = state[e];
    xv[k] = (bv[k] - row[p] * z[v[p]]) * inverse_diagonal[e];
  }
  for (const int e : c.rows_of_two) {
    const long p = begin[e];
    const int k = state[e];
    xv[k] = (bv[k] - row[p] * z[v[p]] - row[p + 1] * z[v[p + 1]]) * inverse_diagonal[e];
  }
  for (const int e : c.rows_of_more) {
    const int k = state[e];
    double sum = bv[k];
    for (long i = begin[e]; i < begin[e + 1]; ++i) sum -= row[i] * z[v[i]];
    xv[k] = sum * inverse_diagonal[e];
  }
  for (int r = 0; r < c.m; ++r) xv[c.kept[r]] = c.z[r];
  c.last_flag = SUNLS_SUCCESS;
  return c.last_flag;
}

sunindextype LastFlag(SUNLinearSolver S) { return Get(S)->last_flag; }

void FreeFactors(Factors& f, klu_l_common& common) {
  if (f.numeric != nullptr) klu_l_free_numeric(&f.numeric, &common);
  if (f.symbolic != nullptr) klu_l_free_symbolic(&f.symbolic, &common);
}

int Free(SUNLinearSolver S) {
  if (S == nullptr) return SUNLS_SUCCESS;
  if (S->content != nullptr) {
    Content* c = Get(S);
    FreeFactors(c->reduced, c->common);
    FreeFactors(c->full, c->common);
    delete c;
    S->content = nullptr;
  }
  SUNLinSolFreeEmpty(S);
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver NewReducedKlu(const std::vector<int>& colptr, const std::vector<int>& rows,
                              const std::vector<std::optional<std::vector<int>>>& speed_rows, SUNContext ctx) {
  const int n = static_cast<int>(colptr.size()) - 1;
  if (static_cast<int>(speed_rows.size()) != n) return nullptr;
  const std::vector<char> eliminated = EliminatedStates(colptr, rows, speed_rows);
  if (std::find(eliminated.begin(), eliminated.end(), 1) == eliminated.end()) return nullptr;
  auto c = std::make_unique<Content>();
  c->n = n;
  std::vector<int> reduced(n, -1);
  for (int j = 0; j < n; ++j)
    if (!eliminated[j]) {
      reduced[j] = static_cast<int>(c->kept.size());
      c->kept.push_back(j);
    }
  c->m = static_cast<int>(c->kept.size());
  // Position of M(i, j) in the compressed columns, -1 when outside the pattern.
  auto position = [&](int i, int j) { return Find(rows, colptr[j], colptr[j + 1], i); };
  // S: the kept columns and rows of M, in M's order.
  Factors& s = c->reduced;
  s.colptr.push_back(0);
  for (int j : c->kept) {
    for (int p = colptr[j]; p < colptr[j + 1]; ++p)
      if (!eliminated[rows[p]]) {
        s.rows.push_back(reduced[rows[p]]);
        c->s_from.push_back(p);
      }
    s.colptr.push_back(static_cast<SuiteSparse_long>(s.rows.size()));
  }
  auto s_position = [&](int i, int j) {  // full indices, both kept
    return Find(s.rows, s.colptr[reduced[j]], s.colptr[reduced[j] + 1], reduced[i]);
  };
  for (int k = 0; k < n; ++k) {
    if (!eliminated[k]) continue;
    Eliminated el;
    el.diagonal = position(k, k);
    const std::vector<int>& row = *speed_rows[k];
    for (int p = colptr[k]; p < colptr[k + 1]; ++p) {
      const int v = rows[p];
      if (v == k) continue;
      if (!eliminated[v]) {
        el.column_pos.push_back(p);
        el.column_v.push_back(reduced[v]);
      }
      if (std::find(row.begin(), row.end(), v) == row.end()) el.zero_pos.push_back(position(k, v));
    }
    for (int v : row) el.row_pos.push_back(position(k, v));
    c->update_begin.push_back(static_cast<long>(c->update_s.size()));
    for (std::size_t i = 0; i < el.column_pos.size(); ++i)
      for (std::size_t j = 0; j < el.row_pos.size(); ++j) {
        const long p = s_position(c->kept[el.column_v[i]], row[j]);
        if (p < 0) return nullptr;  // EliminatedStates guarantees it
        c->update_s.push_back(p);
      }
    c->row_begin.push_back(static_cast<long>(c->row_values.size()));
    c->row_values.resize(c->row_values.size() + el.row_pos.size());
    for (int v : row) c->row_reduced.push_back(reduced[v]);
    c->eliminated_state.push_back(k);
    for (long p : el.row_pos)
      if (p < 0) return nullptr;
    if (el.diagonal < 0) return nullptr;  // the pattern lacks a diagonal: not for this solver
    for (long p : el.zero_pos)
      if (p < 0) return nullptr;  // not structurally symmetric
    c->zero_positions.insert(c->zero_positions.end(), el.zero_pos.begin(), el.zero_pos.end());
    c->eliminated.push_back(std::move(el));
  }
  c->identity.assign(rows.size(), 0.0);
  c->m_values.assign(rows.size(), 0.0);
  for (int j = 0; j < n; ++j) {
    const long p = position(j, j);
    if (p < 0) return nullptr;  // the pattern lacks a diagonal: not for this solver
    c->identity[p] = 1.0;
  }
  s.values.assign(s.rows.size(), 0.0);
  c->full.colptr.assign(colptr.begin(), colptr.end());
  c->full.rows.assign(rows.begin(), rows.end());
  c->full.values.assign(rows.size(), 0.0);
  c->inverse_diagonal.assign(c->eliminated.size(), 0.0);
  std::size_t column_entries = 0;
  for (const Eliminated& el : c->eliminated) column_entries += el.column_pos.size();
  c->active_v.assign(column_entries, 0);
  c->active_e.assign(column_entries, 0);
  c->active_values.assign(column_entries, 0.0);
  c->xk.assign(c->eliminated.size(), 0.0);
  c->z.assign(c->m, 0.0);
  c->row_begin.push_back(static_cast<long>(c->row_values.size()));
  for (std::size_t e = 0; e < c->eliminated.size(); ++e) {
    const long length = c->row_begin[e + 1] - c->row_begin[e];
    (length == 1 ? c->rows_of_one : length == 2 ? c->rows_of_two : c->rows_of_more).push_back(static_cast<int>(e));
  }
  klu_l_defaults(&c->common);
  c->common.ordering = 0;  // AMD: the pattern is structurally symmetric

  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (S == nullptr) return nullptr;
  S->ops->gettype = GetType;
  S->ops->getid = GetId;
  S->ops->initialize = Initialize;
  S->ops->setup = Setup;
  S->ops->solve = Solve;
  S->ops->lastflag = LastFlag;
  S->ops->free = Free;
  S->content = c.release();
  return S;
}

int ReducedKluSize(SUNLinearSolver S) { return Get(S)->m; }

long ReducedKluFullSetups(SUNLinearSolver S) { return Get(S)->full_setups; }

void ReducedKluSetGamma(SUNLinearSolver S, double gamma) {
  Get(S)->given_jacobian = true;
  Get(S)->gamma = gamma;
}

}  // namespace highlift::sim::detail
