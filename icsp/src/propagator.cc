#include "highlift/icsp/propagator.h"

#include <algorithm>
#include <bit>
#include <cfenv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/core/units.h"
#include "highlift/core/message_number.h"

namespace highlift::icsp {

using FI = FastInterval;

std::string ToString(Schedule s) {
  switch (s) {
    case Schedule::kFifo: return "fifo";
    case Schedule::kLifo: return "lifo";
    case Schedule::kSweep: return "sweep";
  }
  return "?";
}
std::optional<Schedule> ScheduleFromString(const std::string& s) {
  for (Schedule k : {Schedule::kFifo, Schedule::kLifo, Schedule::kSweep}) {
    if (ToString(k) == s) return k;
  }
  return std::nullopt;
}

std::string ToString(Status s) {
  switch (s) {
    case Status::kFixedPoint: return "fixed_point";
    case Status::kInfeasible: return "infeasible";
    case Status::kStoppedAtLimit: return "stopped_at_limit";
  }
  return "?";
}
std::optional<Status> StatusFromString(const std::string& s) {
  for (Status k : {Status::kFixedPoint, Status::kInfeasible, Status::kStoppedAtLimit}) {
    if (ToString(k) == s) return k;
  }
  return std::nullopt;
}

void PropagationOptions::Validate() const {
  if (!(ratio >= 0.0 && ratio < 1.0)) {
    throw InputError("icsp: propagation ratio " + FormatMessageNumber(ratio) +
                     " is outside [0, 1); use 0 for the exact fixed point or e.g. 0.01");
  }
  if (max_revisions <= 0) {
    throw InputError("icsp: max_revisions " + std::to_string(max_revisions) + " must be > 0");
  }
  if (!(max_seconds > 0.0)) {
    throw InputError("icsp: max_seconds " + FormatMessageNumber(max_seconds) + " must be > 0");
  }
}

void ShavingOptions::Validate() const {
  if (slices < 2) throw InputError("icsp: shaving slices " + std::to_string(slices) + " must be >= 2");
  if (max_propagations < 0) {
    throw InputError("icsp: shaving max_propagations " + std::to_string(max_propagations) + " must be >= 0");
  }
}

std::string PropagationReport::BriefReport() const {
  char buf[256];
  const char* what = status == Status::kFixedPoint   ? "fixed point"
                     : status == Status::kInfeasible ? "proved infeasible"
                                                     : "stopped at a limit";
  std::snprintf(buf, sizeof buf, "%s after %lld revisions (%.3g ms)", what,
                static_cast<long long>(revisions), seconds * 1e3);
  std::string s = buf;
  if (!message.empty()) s += ": " + message;
  return s;
}

std::string PropagationReport::FullReport() const {
  TextTable t({"quantity", "value"}, {1});
  t.AddRow({"status", ToString(status)});
  t.AddRow({"revisions", std::to_string(revisions)});
  t.AddRow({"narrowings", std::to_string(narrowings)});
  t.AddRow({"re-queued constraints", std::to_string(requeued)});
  t.AddRow({"time [ms]", FormatNumber(seconds * 1e3, 4)});
  if (empty_variable >= 0) t.AddRow({"empty variable", std::to_string(empty_variable)});
  if (empty_constraint >= 0) t.AddRow({"empty at constraint", std::to_string(empty_constraint)});
  std::string s = BriefReport() + "\n" + t.ToString();
  return s;
}

namespace {

/// Pending constraints. Sweep order uses a two-level bitset so that finding the next pending
/// constraint in either direction costs a few word operations.
class Agenda {
 public:
  Agenda(int n, Schedule schedule) : n_(n), schedule_(schedule) {
    words_.assign((n + 63) / 64, 0);
    summary_.assign((words_.size() + 63) / 64, 0);
    if (schedule != Schedule::kSweep) list_.reserve(n);
  }
  bool empty() const { return count_ == 0; }
  bool Push(int c) {
    std::uint64_t& w = words_[c >> 6];
    const std::uint64_t bit = std::uint64_t{1} << (c & 63);
    if (w & bit) return false;
    w |= bit;
    summary_[c >> 12] |= std::uint64_t{1} << ((c >> 6) & 63);
    ++count_;
    if (schedule_ != Schedule::kSweep) list_.push_back(c);
    return true;
  }
  int Pop() {
    int c;
    if (schedule_ == Schedule::kFifo) {
      c = list_[head_++];
      if (head_ > 4096 && head_ * 2 > list_.size()) {
        list_.erase(list_.begin(), list_.begin() + static_cast<std::ptrdiff_t>(head_));
        head_ = 0;
      }
    } else if (schedule_ == Schedule::kLifo) {
      c = list_.back();
      list_.pop_back();
    } else {
      c = forward_ ? NextFrom(cursor_) : PrevFrom(cursor_);
      if (c < 0) {
        forward_ = !forward_;
        c = forward_ ? NextFrom(0) : PrevFrom(n_ - 1);
      }
      cursor_ = forward_ ? c + 1 : c - 1;
    }
    Clear(c);
    return c;
  }

 private:
  void Clear(int c) {
    std::uint64_t& w = words_[c >> 6];
    w &= ~(std::uint64_t{1} << (c & 63));
    if (w == 0) summary_[c >> 12] &= ~(std::uint64_t{1} << ((c >> 6) & 63));
    --count_;
  }
  int NextFrom(int c) const {
    if (c >= n_) return -1;
    int wi = c >> 6;
    std::uint64_t w = words_[wi] & (~std::uint64_t{0} << (c & 63));
    if (w) return (wi << 6) + std::countr_zero(w);
    // next non-empty word after wi
    int si = (wi + 1) >> 6;
    if (((wi + 1) & 63) != 0 || si < static_cast<int>(summary_.size())) {
      if (si < static_cast<int>(summary_.size())) {
        std::uint64_t s = summary_[si] & (((wi + 1) & 63) ? (~std::uint64_t{0} << ((wi + 1) & 63)) : ~std::uint64_t{0});
        while (true) {
          if (s) {
            const int word = (si << 6) + std::countr_zero(s);
            return (word << 6) + std::countr_zero(words_[word]);
          }
          if (++si >= static_cast<int>(summary_.size())) break;
          s = summary_[si];
        }
      }
    }
    return -1;
  }
  int PrevFrom(int c) const {
    if (c < 0) return -1;
    int wi = c >> 6;
    const int shift = 63 - (c & 63);
    std::uint64_t w = words_[wi] & (~std::uint64_t{0} >> shift);
    if (w) return (wi << 6) + 63 - std::countl_zero(w);
    if (wi == 0) return -1;
    const int prev = wi - 1;
    int si = prev >> 6;
    std::uint64_t s = summary_[si] & (~std::uint64_t{0} >> (63 - (prev & 63)));
    while (true) {
      if (s) {
        const int word = (si << 6) + 63 - std::countl_zero(s);
        return (word << 6) + 63 - std::countl_zero(words_[word]);
      }
      if (--si < 0) break;
      s = summary_[si];
    }
    return -1;
  }

  int n_;
  Schedule schedule_;
  std::vector<std::uint64_t> words_, summary_;
  std::vector<int> list_;
  std::size_t head_ = 0;
  std::int64_t count_ = 0;
  int cursor_ = 0;
  bool forward_ = true;
};

inline FI ToFast(const Interval& x) { return FI(x.lower(), x.upper(), true); }
inline Interval ToSafe(const FI& x) { return Interval(x.lower(), x.upper(), true); }

FI RelationRange(Relation r) {
  switch (r) {
    case Relation::kEqual: return FI(0.0, 0.0, true);
    case Relation::kLessEqual: return FI(-kInf, 0.0, true);
    case Relation::kGreaterEqual: return FI(0.0, kInf, true);
  }
  return FI::whole();
}

/// Evaluates a monotone function at a point in round-to-nearest, as its author expects.
double CallNearest(const MonotoneFunction& m, const std::vector<double>& x) {
  std::fesetround(FE_TONEAREST);
  const double y = m.f(std::span<const double>(x.data(), x.size()));
  std::fesetround(FE_UPWARD);
  return y;
}

/// Outward widening of a computed function value by its declared relative error.
double Down(const MonotoneFunction& m, double y) {
  if (std::isnan(y)) return -kInf;
  return std::nextafter(y - m.relative_error * std::fabs(y), -kInf);
}
double Up(const MonotoneFunction& m, double y) {
  if (std::isnan(y)) return kInf;
  return std::nextafter(y + m.relative_error * std::fabs(y), kInf);
}

}  // namespace

namespace detail {

/// One propagation run over a compiled network (Propagator's tape).
class Engine {
 public:
  using Step = Propagator::Step;
  using SharedBlock = Propagator::SharedBlock;
  explicit Engine(Propagator& p)
      : net_(p.network_), opt_(p.options_), lo_reason_(p.lower_reason_), hi_reason_(p.upper_reason_),
        narrowed_(p.narrowed_),
        tape_(p.tape_), tape_begin_(p.tape_begin_), constants_(p.constants_), blocks_(p.blocks_),
        blocks_begin_(p.blocks_begin_), shared_vars_(p.shared_vars_), shared_vars_begin_(p.shared_vars_begin_) {
    val_.resize(static_cast<std::size_t>(p.max_steps_) + 1);
    monotone_memo_.resize(static_cast<std::size_t>(net_.num_monotone()));
    reuse_ = opt_.reuse_shared_subexpressions && p.num_shared_ > 0;
    shared_value_.resize(static_cast<std::size_t>(p.num_shared_));
    shared_time_.assign(static_cast<std::size_t>(p.num_shared_), -1);
  }

  PropagationReport Run(Box& box, const std::vector<char>& enabled) {
    PropagationReport report;
    const auto t0 = std::chrono::steady_clock::now();
    const int nc = net_.num_constraints();
    if (opt_.record_reasons) {
      lo_reason_.assign(box.size(), BoundReason{});
      hi_reason_.assign(box.size(), BoundReason{});
      const int scopes = nc > 0 ? net_.constraint(ConstraintId{nc - 1}).vars_end : 0;
      narrowed_.assign(static_cast<std::size_t>(scopes), 0);
    } else {
      narrowed_.clear();
    }
    for (const Interval& d : box) {
      if (IsEmpty(d)) {
        report.status = Status::kInfeasible;
        report.empty_variable = static_cast<int>(&d - box.data());
        report.message = "variable '" + net_.variable(VariableId{report.empty_variable}).name +
                         "' starts with an empty domain";
        return report;
      }
    }
    Agenda agenda(nc, opt_.schedule);
    enabled_ = enabled.empty() ? nullptr : &enabled;
    report_ = &report;
    if (reuse_) changed_at_.assign(box.size(), -1);
    for (int c = 0; c < nc; ++c) {
      if (!enabled_ || (*enabled_)[c]) agenda.Push(c);
    }
    box_ = &box;
    bool out_of_time = false;
    {
    RoundingGuard guard;  // upward rounding for the whole loop (FastInterval arithmetic)
    while (!agenda.empty()) {
      if (report.revisions >= opt_.max_revisions) {
        report.status = Status::kStoppedAtLimit;
        report.message = "reached max_revisions = " + std::to_string(opt_.max_revisions);
        break;
      }
      if ((report.revisions & 1023) == 1023 &&
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > opt_.max_seconds) {
        report.status = Status::kStoppedAtLimit;
        out_of_time = true;
        break;
      }
      const int c = agenda.Pop();
      ++report.revisions;
      changed_.clear();
      const bool ok = Revise(c, report.revisions);
      if (!ok) {
        report.status = Status::kInfeasible;
        report.empty_constraint = c;
        report.empty_variable = empty_variable_;
        const auto& info = net_.constraint(ConstraintId{c}).info;
        const std::string label = "'" + (info.label.empty() ? std::to_string(c) : info.label) + "'";
        report.message = empty_variable_ >= 0
            ? "the domain of '" + net_.variable(VariableId{empty_variable_}).name + "' ran empty at constraint " + label
            : "constraint " + label + " cannot hold for any values in the narrowed domains";
        break;
      }
      for (const auto& [v, significant] : changed_) {
        ++report.narrowings;
        if (!significant) continue;
        for (int other : net_.ConstraintsOf(VariableId{v})) {
          if (enabled_ && !(*enabled_)[other]) continue;
          if (other == c && !opt_.requeue_self) continue;
          if (agenda.Push(other)) ++report.requeued;
        }
      }
    }
    }  // rounding mode restored: formatting below runs in round-to-nearest
    if (out_of_time) report.message = "reached max_seconds = " + FormatNumber(opt_.max_seconds, 3) + " s";
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (report.status == Status::kFixedPoint) {
      report.message = opt_.ratio > 0.0 ? "no domain shrinks by more than the ratio " + FormatNumber(opt_.ratio, 3)
                                        : "no bound changes any more";
    }
    return report;
  }

 private:
  /// Writes back a narrowed domain; false when empty.
  bool Update(int v, const FI& narrowed, int c, std::int64_t time) {
    Interval& d = (*box_)[v];
    if (IsEmpty(narrowed)) {
      empty_variable_ = v;
      return false;
    }
    const double lo = std::max(d.lower(), narrowed.lower());
    const double hi = std::min(d.upper(), narrowed.upper());
    if (!(lo <= hi)) {
      empty_variable_ = v;
      return false;
    }
    const bool lo_moved = lo > d.lower();
    const bool hi_moved = hi < d.upper();
    if (!lo_moved && !hi_moved) return true;
    bool significant = true;
    if (opt_.ratio > 0.0) {
      const double old_w = d.upper() - d.lower();
      const double new_w = hi - lo;
      if (std::isfinite(old_w)) significant = (old_w - new_w) > opt_.ratio * old_w;
      else significant = std::isfinite(new_w) || (lo_moved && !std::isfinite(d.lower())) ||
                         (hi_moved && !std::isfinite(d.upper()));
    }
    if (opt_.record_reasons) {
      if (lo_moved) lo_reason_[v] = {c, time};
      if (hi_moved) hi_reason_[v] = {c, time};
      const auto scope = net_.ScopeOf(ConstraintId{c});
      for (std::size_t i = 0; i < scope.size(); ++i) {
        if (scope[i] == v) {
          narrowed_[net_.constraint(ConstraintId{c}).vars_begin + i] = 1;
          break;
        }
      }
    }
    if (reuse_) changed_at_[v] = time;
    d = Interval(lo, hi, true);
    changed_.push_back({v, significant});
    return true;
  }

  bool Revise(int c, std::int64_t time) {
    empty_variable_ = -1;
    const Constraint& k = net_.constraint(ConstraintId{c});
    if (k.kind == Constraint::Kind::kMonotone) return ReviseMonotone(c, k, time);
    const Step* steps = tape_.data() + tape_begin_[c];
    const int count = tape_begin_[c + 1] - tape_begin_[c];
    const Box& box = *box_;
    FI* val = val_.data();
    const SharedBlock* block = blocks_.data() + blocks_begin_[c];
    const SharedBlock* const blocks_end = blocks_.data() + blocks_begin_[c + 1];
    // Forward: evaluate every node once (operands first). A subexpression that other constraints
    // share keeps its value while none of its variables changes: then its steps are copied.
    for (int k = 0; k < count; ++k) {
      if (block != blocks_end && block->begin == k) {
        const SharedBlock& b = *block++;
        if (reuse_ && Valid(b.shared)) {
          for (int j = b.begin; j <= b.top; ++j) {
            const Step& n = steps[j];
            val[j] = n.op == Op::kVar     ? ToFast(box[n.a])
                     : n.op == Op::kConst ? ToFast(constants_[n.aux])
                                          : shared_value_[n.shared];
          }
          ++report_->reused_subexpressions;
          k = b.top;
          continue;
        }
      }
      const Step& n = steps[k];
      FI& y = val[k];
      switch (n.op) {
        case Op::kVar: y = ToFast(box[n.a]); break;
        case Op::kConst: y = ToFast(constants_[n.aux]); break;
        case Op::kAdd: y = val[n.a] + val[n.b]; break;
        case Op::kSub: y = val[n.a] - val[n.b]; break;
        case Op::kMul: y = val[n.a] * val[n.b]; break;
        case Op::kDiv: y = icsp::Div(val[n.a], val[n.b]); break;
        case Op::kNeg: y = -val[n.a]; break;
        case Op::kSqr: y = icsp::Sqr(val[n.a]); break;
        case Op::kPowInt: y = icsp::PowInt(val[n.a], n.aux); break;
        case Op::kPowReal: y = icsp::PowReal(val[n.a], constants_[n.aux].lower()); break;
        case Op::kSqrt: y = icsp::Sqrt(val[n.a]); break;
        case Op::kExp: y = icsp::Exp(val[n.a]); break;
        case Op::kLog: y = icsp::Log(val[n.a]); break;
        case Op::kAbs: y = icsp::Abs(val[n.a]); break;
        case Op::kMin: y = icsp::Min(val[n.a], val[n.b]); break;
        case Op::kMax: y = icsp::Max(val[n.a], val[n.b]); break;
        case Op::kSin: y = icsp::Sin(val[n.a]); break;
        case Op::kCos: y = icsp::Cos(val[n.a]); break;
      }
      if (n.shared >= 0) {
        shared_value_[n.shared] = y;
        shared_time_[n.shared] = time;
      }
      if (IsEmpty(y)) return false;
    }
    // The relation (the root is the last step).
    FI& root = val[count - 1];
    root = Meet(root, RelationRange(k.relation));
    if (IsEmpty(root)) return false;
    // Backward: project each node's narrowed value onto its operands (parents before children).
    for (int k2 = count - 1; k2 >= 0; --k2) {
      const Step& n = steps[k2];
      const FI& y = val[k2];
      switch (n.op) {
        case Op::kVar:
        case Op::kConst: continue;
        case Op::kAdd: {
          FI& a = val[n.a];
          a = AddBackward(y, a, val[n.b]);
          if (IsEmpty(a)) return false;
          FI& b = val[n.b];
          b = AddBackward(y, b, val[n.a]);
          if (IsEmpty(b)) return false;
          continue;
        }
        case Op::kSub: {
          FI& a = val[n.a];
          a = SubBackwardLeft(y, a, val[n.b]);
          if (IsEmpty(a)) return false;
          FI& b = val[n.b];
          b = SubBackwardRight(y, val[n.a], b);
          if (IsEmpty(b)) return false;
          continue;
        }
        case Op::kMul: {
          FI& a = val[n.a];
          a = MulBackward(y, a, val[n.b]);
          if (IsEmpty(a)) return false;
          FI& b = val[n.b];
          b = MulBackward(y, b, val[n.a]);
          if (IsEmpty(b)) return false;
          continue;
        }
        case Op::kDiv: {
          FI& a = val[n.a];
          a = DivBackwardLeft(y, a, val[n.b]);
          if (IsEmpty(a)) return false;
          FI& b = val[n.b];
          b = DivBackwardRight(y, val[n.a], b);
          if (IsEmpty(b)) return false;
          continue;
        }
        case Op::kMin:
        case Op::kMax: {
          FI& a = val[n.a];
          FI& b = val[n.b];
          const FI a0 = a;
          a = n.op == Op::kMin ? MinBackward(y, a, b) : MaxBackward(y, a, b);
          if (IsEmpty(a)) return false;
          b = n.op == Op::kMin ? MinBackward(y, b, a0) : MaxBackward(y, b, a0);
          if (IsEmpty(b)) return false;
          continue;
        }
        default: break;
      }
      FI& a = val[n.a];
      switch (n.op) {
        case Op::kNeg: a = NegBackward(y, a); break;
        case Op::kSqr: a = SqrBackward(y, a); break;
        case Op::kPowInt: a = PowIntBackward(y, a, n.aux); break;
        case Op::kPowReal: a = PowRealBackward(y, a, constants_[n.aux].lower()); break;
        case Op::kSqrt: a = SqrtBackward(y, a); break;
        case Op::kExp: a = ExpBackward(y, a); break;
        case Op::kLog: a = LogBackward(y, a); break;
        case Op::kAbs: a = AbsBackward(y, a); break;
        case Op::kSin: a = SinBackward(y, a); break;
        case Op::kCos: a = CosBackward(y, a); break;
        default: break;
      }
      if (IsEmpty(a)) return false;
    }
    // Write back the variables.
    for (int k3 = 0; k3 < count; ++k3) {
      if (steps[k3].op != Op::kVar) continue;
      if (!Update(steps[k3].a, val[k3], c, time)) return false;
    }
    return true;
  }

  bool ReviseMonotone(int c, const Constraint& k, std::int64_t time) {
    const MonotoneFunction& m = net_.monotone(k.monotone);
    const auto scope = net_.ScopeOf(ConstraintId{c});
    const int y = scope[0];
    const std::size_t n = scope.size() - 1;
    const Box& box = *box_;
    // Corner giving the smallest (low = true) or largest value of f.
    auto corner = [&](bool low, std::vector<double>& x) {
      x.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        const Interval& d = box[scope[i + 1]];
        const bool inc = m.monotonicity[i] == Monotonicity::kIncreasing;
        x[i] = (low == inc) ? d.lower() : d.upper();
      }
    };
    auto finite = [](const std::vector<double>& x) {
      return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
    };
    std::vector<double> xlo, xhi;
    corner(true, xlo);
    corner(false, xhi);
    // The corners of the last revision of this constraint are remembered: an unchanged corner is
    // not evaluated again (a black box may be a costly computation, e.g. an eigenvalue).
    MonotoneMemo& memo = monotone_memo_[k.monotone];
    if (!memo.valid || memo.xlo != xlo) {
      memo.flo = finite(xlo) ? Down(m, CallNearest(m, xlo)) : -kInf;
      memo.xlo = xlo;
    }
    if (!memo.valid || memo.xhi != xhi) {
      memo.fhi = finite(xhi) ? Up(m, CallNearest(m, xhi)) : kInf;
      memo.xhi = xhi;
    }
    memo.valid = true;
    const double flo = memo.flo, fhi = memo.fhi;
    if (!Update(y, FI(std::min(flo, fhi), std::max(flo, fhi), true), c, time)) return false;
    const Interval yd = box[y];
    // Backward projection can only cut where y is narrower than the image of the box: when
    // y.lo <= min f, every x_i meets y.lo (side 0 has nothing to cut), likewise y.hi >= max f.
    const bool cut_by_lower = yd.lower() > std::min(flo, fhi);
    const bool cut_by_upper = yd.upper() < std::max(flo, fhi);
    if (!cut_by_lower && !cut_by_upper) return true;
    // Backward on each argument: with the others at the corner that favours the bound, bisect
    // for the last value of x_i that is still infeasible (everything beyond it is cut off).
    for (std::size_t i = 0; i < n; ++i) {
      const int v = scope[i + 1];
      const bool inc = m.monotonicity[i] == Monotonicity::kIncreasing;
      Interval d = box[v];
      if (!std::isfinite(d.lower()) || !std::isfinite(d.upper())) continue;
      // A point argument has nothing to cut: with x_i at its only value, the largest and
      // smallest f over the box are max f and min f, and y meets [min f, max f].
      if (d.lower() == d.upper()) continue;
      // f_max(t): largest f over the box with x_i = t; rises with t when inc.
      // Lower bound of x_i (inc): need f_max(t) >= y.lo. Upper bound (inc): need f_min(t) <= y.hi.
      for (int side = 0; side < 2; ++side) {
        const bool use_max = (side == 0);  // side 0 uses f_max against y.lo, side 1 f_min against y.hi
        if (use_max ? !cut_by_lower : !cut_by_upper) continue;
        std::vector<double> x;
        corner(!use_max, x);
        if (!finite(x)) continue;
        auto feasible = [&](double t) {
          x[i] = t;
          const double f = CallNearest(m, x);
          return use_max ? Up(m, f) >= yd.lower() : Down(m, f) <= yd.upper();
        };
        // Infeasible end: for inc and f_max, small t is infeasible (cut the lower bound).
        const bool cut_lower = (use_max == inc);
        double good = cut_lower ? d.upper() : d.lower();
        double bad = cut_lower ? d.lower() : d.upper();
        if (feasible(bad)) continue;
        if (!feasible(good)) {
          empty_variable_ = v;
          return false;
        }
        for (int s = 0; s < m.bisection_steps; ++s) {
          const double mid = 0.5 * (good + bad);
          if (mid == good || mid == bad) break;
          if (feasible(mid)) good = mid; else bad = mid;
        }
        d = cut_lower ? Interval(bad, d.upper(), true) : Interval(d.lower(), bad, true);
      }
      if (!Update(v, ToFast(d), c, time)) return false;
    }
    return true;
  }

  /// The kept value of shared entry e was computed from the current domains of its variables.
  bool Valid(int e) const {
    const std::int64_t t = shared_time_[e];
    if (t < 0) return false;
    for (int k = shared_vars_begin_[e]; k < shared_vars_begin_[e + 1]; ++k) {
      if (changed_at_[shared_vars_[k]] >= t) return false;
    }
    return true;
  }

  const Network& net_;
  const PropagationOptions& opt_;
  std::vector<BoundReason>& lo_reason_;
  std::vector<BoundReason>& hi_reason_;
  std::vector<char>& narrowed_;
  const std::vector<Step>& tape_;
  const std::vector<int>& tape_begin_;
  const std::vector<Interval>& constants_;
  const std::vector<SharedBlock>& blocks_;
  const std::vector<int>& blocks_begin_;
  const std::vector<int>& shared_vars_;
  const std::vector<int>& shared_vars_begin_;
  bool reuse_ = false;
  std::vector<FI> shared_value_;          ///< per shared entry: its last forward value
  std::vector<std::int64_t> shared_time_; ///< ... and the revision that computed it (-1: none)
  std::vector<std::int64_t> changed_at_;  ///< per variable: the revision that last narrowed it
  PropagationReport* report_ = nullptr;
  std::vector<FI> val_;
  std::vector<std::pair<int, bool>> changed_;
  Box* box_ = nullptr;
  const std::vector<char>* enabled_ = nullptr;
  int empty_variable_ = -1;
  /// Per monotone function: the corners of its last forward evaluation and their values.
  struct MonotoneMemo {
    bool valid = false;
    std::vector<double> xlo, xhi;
    double flo = 0.0, fhi = 0.0;
  };
  std::vector<MonotoneMemo> monotone_memo_;
};

}  // namespace detail

Propagator::Propagator(const Network& network, PropagationOptions options)
    : network_(network), options_(options) {
  options_.Validate();
  Compile();
}

void Propagator::Compile() {
  // Each expression constraint becomes a contiguous tape of steps over its DAG nodes, so that a
  // revision reads one short array and a small scratch buffer instead of the whole node table.
  const int nc = network_.num_constraints();
  const std::size_t num_nodes = static_cast<std::size_t>(network_.num_nodes());
  tape_.clear();
  constants_.clear();
  blocks_.clear();
  max_steps_ = 0;
  tape_begin_.assign(static_cast<std::size_t>(nc) + 1, 0);
  blocks_begin_.assign(static_cast<std::size_t>(nc) + 1, 0);
  // Subexpressions that two or more constraints share (hash-consing made them one node).
  std::vector<int> users(num_nodes, 0);
  for (int c = 0; c < nc; ++c) {
    for (int id : network_.TopoOf(ConstraintId{c})) ++users[id];
  }
  std::vector<int> shared_of(num_nodes, -1);
  std::vector<int> shared_node;  // entry -> node
  for (std::size_t id = 0; id < num_nodes; ++id) {
    const Op op = network_.node(ExprId{static_cast<int>(id)}).op;
    if (users[id] >= 2 && op != Op::kVar && op != Op::kConst) {
      shared_of[id] = static_cast<int>(shared_node.size());
      shared_node.push_back(static_cast<int>(id));
    }
  }
  num_shared_ = static_cast<int>(shared_node.size());
  std::vector<char> is_top(shared_node.size(), 0);

  std::vector<int> local(num_nodes, -1);
  std::vector<int> stamp(num_nodes, -1), start(num_nodes, 0);
  std::vector<int> begin_of;  // per step of the constraint: first step of its fresh subtree
  std::vector<std::pair<int, int>> stack;
  std::vector<SharedBlock> found;
  for (int c = 0; c < nc; ++c) {
    tape_begin_[c] = static_cast<int>(tape_.size());
    blocks_begin_[c] = static_cast<int>(blocks_.size());
    const Constraint& k = network_.constraint(ConstraintId{c});
    if (k.kind != Constraint::Kind::kExpression) continue;
    const auto topo = network_.TopoOf(ConstraintId{c});
    for (std::size_t i = 0; i < topo.size(); ++i) {
      const ExprNode& n = network_.node(ExprId{topo[i]});
      Step s;
      s.op = n.op;
      s.shared = shared_of[topo[i]];
      switch (n.op) {
        case Op::kVar: s.a = n.a; break;
        case Op::kConst:
          s.aux = static_cast<int>(constants_.size());
          constants_.push_back(n.value);
          break;
        case Op::kPowInt:
          s.a = local[n.a];
          s.aux = n.n;
          break;
        case Op::kPowReal:
          s.a = local[n.a];
          s.aux = static_cast<int>(constants_.size());
          constants_.push_back(Interval(n.p, n.p, true));
          break;
        default:
          s.a = local[n.a];
          s.b = n.b >= 0 ? local[n.b] : -1;
          break;
      }
      local[topo[i]] = static_cast<int>(i);
      tape_.push_back(s);
    }
    HIGHLIFT_CHECK(!topo.empty() && topo.back() == k.root, "icsp: the root must end the evaluation order");
    // The network's evaluation order is a post-order depth-first walk (Network::IndexConstraint);
    // walking it again gives each step the range of steps its subtree was emitted in.
    begin_of.assign(topo.size(), 0);
    int emitted = 0;
    stack.assign(1, {k.root, 0});
    stamp[k.root] = c;
    start[k.root] = 0;
    while (!stack.empty()) {
      auto& [node, state] = stack.back();
      const ExprNode& n = network_.node(ExprId{node});
      const int child = state == 0 ? (n.op == Op::kVar || n.op == Op::kConst ? -1 : n.a) : state == 1 ? n.b : -1;
      if (state < 2) {
        ++state;
        if (child >= 0 && stamp[child] != c) {
          stamp[child] = c;
          start[child] = emitted;
          stack.push_back({child, 0});
        }
        continue;
      }
      HIGHLIFT_CHECK(emitted < static_cast<int>(topo.size()) && topo[emitted] == node,
                     "icsp: the evaluation order is not the post-order walk of the expression");
      begin_of[emitted] = start[node];
      ++emitted;
      stack.pop_back();
    }
    // The outermost shared subexpressions (blocks nest: a shared node's operands are shared too).
    found.clear();
    int covered_from = static_cast<int>(topo.size());
    for (int i = static_cast<int>(topo.size()) - 1; i >= 0; --i) {
      const int e = shared_of[topo[i]];
      if (e < 0 || i >= covered_from) continue;
      for (int j = begin_of[i]; j <= i; ++j) {
        const Step& inner = tape_[tape_begin_[c] + j];
        HIGHLIFT_CHECK(inner.op == Op::kVar || inner.op == Op::kConst || inner.shared >= 0,
                       "icsp: an operand of a shared subexpression must be shared too");
      }
      found.push_back({begin_of[i], i, e});
      is_top[e] = 1;
      covered_from = begin_of[i];
    }
    blocks_.insert(blocks_.end(), found.rbegin(), found.rend());
    for (int id : topo) local[id] = -1;
    max_steps_ = std::max(max_steps_, static_cast<int>(topo.size()));
  }
  tape_begin_[nc] = static_cast<int>(tape_.size());
  blocks_begin_[nc] = static_cast<int>(blocks_.size());
  // The variables below each outermost shared subexpression: its kept value is valid while none
  // of them has changed.
  shared_vars_.clear();
  shared_vars_begin_.assign(shared_node.size() + 1, 0);
  std::vector<int> seen(num_nodes, -1), todo;
  for (std::size_t e = 0; e < shared_node.size(); ++e) {
    shared_vars_begin_[e] = static_cast<int>(shared_vars_.size());
    if (!is_top[e]) continue;
    todo.assign(1, shared_node[e]);
    seen[shared_node[e]] = static_cast<int>(e);
    while (!todo.empty()) {
      const int id = todo.back();
      todo.pop_back();
      const ExprNode& n = network_.node(ExprId{id});
      if (n.op == Op::kVar) {
        shared_vars_.push_back(n.a);
        continue;
      }
      if (n.op == Op::kConst) continue;
      for (int child : {n.a, n.b}) {
        if (child >= 0 && seen[child] != static_cast<int>(e)) {
          seen[child] = static_cast<int>(e);
          todo.push_back(child);
        }
      }
    }
  }
  shared_vars_begin_[shared_node.size()] = static_cast<int>(shared_vars_.size());
}

void Propagator::set_options(const PropagationOptions& o) {
  o.Validate();
  options_ = o;
}

PropagationReport Propagator::Propagate(Box& box, const std::vector<char>& enabled) {
  HIGHLIFT_CHECK(static_cast<int>(box.size()) == network_.num_variables(),
                 "icsp: box size differs from the number of variables");
  HIGHLIFT_CHECK(enabled.empty() || static_cast<int>(enabled.size()) == network_.num_constraints(),
                 "icsp: enabled mask size differs from the number of constraints");
  detail::Engine engine(*this);
  return engine.Run(box, enabled);
}

PropagationReport Propagate(const Network& network, Box& box, const PropagationOptions& options) {
  Propagator p(network, options);
  return p.Propagate(box);
}

namespace {
std::string Label(const Network& net, int c) {
  const auto& info = net.constraint(ConstraintId{c}).info;
  return info.label.empty() ? "constraint " + std::to_string(c) : info.label;
}
/// A formula for a reader: a monotone black box with its first arguments, a long expression
/// cut after about `limit` characters.
std::string ShortText(const Network& net, int c, std::size_t limit = 160) {
  const Constraint& k = net.constraint(ConstraintId{c});
  if (k.kind == Constraint::Kind::kMonotone) {
    const auto scope = net.ScopeOf(ConstraintId{c});
    std::string out = net.variable(VariableId{scope[0]}).name + " == f(";
    const std::size_t args = scope.size() - 1;
    if (args > 4) out += std::to_string(args) + " parameters: ";
    for (std::size_t i = 1; i < scope.size() && i <= 3; ++i) out += (i > 1 ? ", " : "") + net.variable(VariableId{scope[i]}).name;
    return out + (args > 3 ? ", ...)" : ")");
  }
  // The requirement as the engineer wrote it (with its units); physics as the network holds it.
  std::string text = k.info.role == ConstraintRole::kRequirement && !k.info.source.empty()
                         ? k.info.source
                         : net.ConstraintText(ConstraintId{c});
  if (text.size() > limit) {
    std::size_t cut = text.rfind(' ', limit - 10);
    if (cut == std::string::npos || cut < limit / 2) cut = limit - 10;
    text = text.substr(0, cut) + " ...";
  }
  return text;
}
std::string Describe(const Network& net, int c) {
  const auto& info = net.constraint(ConstraintId{c}).info;
  std::string s = (info.role == ConstraintRole::kRequirement ? "requirement '" : "'") + Label(net, c) + "'";
  if (!info.description.empty()) s += " (" + info.description + ")";
  s += ": " + ShortText(net, c);
  return s;
}
/// A bound in the variable's display unit, e.g. "263.8 rpm" (SI when the unit is not known).
std::string Value(const Network& net, int v, double x) {
  const auto& var = net.variable(VariableId{v});
  x += 0.0;  // -0 prints as 0
  if (var.unit.empty() || var.unit == "1") return FormatNumber(x, 6);
  try {
    const UnitConversion u = ParseUnit(var.unit);
    return FormatNumber((x - u.offset) / u.scale, 6) + " " + var.unit;
  } catch (const InputError&) {
    return FormatNumber(x, 6) + " (SI)";
  }
}
/// "x in [a, b] unit", "x = a unit", "x >= a unit" for a domain.
std::string DomainText(const Network& net, int v, const Interval& d) {
  const std::string& name = net.variable(VariableId{v}).name;
  if (IsEmpty(d)) return name + " empty";
  const bool lo = std::isfinite(d.lower()), hi = std::isfinite(d.upper());
  if (lo && hi) {
    const std::string a = Value(net, v, d.lower()), b = Value(net, v, d.upper());
    if (a == b) return name + " = " + a;
    const auto& unit = net.variable(VariableId{v}).unit;
    const std::string suffix = unit.empty() || unit == "1" || a.find(' ') == std::string::npos ? "" : a.substr(a.find(' '));
    auto number = [&](const std::string& t) { return suffix.empty() ? t : t.substr(0, t.find(' ')); };
    return name + " in [" + number(a) + ", " + number(b) + "]" + suffix;
  }
  if (lo) return name + " >= " + Value(net, v, d.lower());
  if (hi) return name + " <= " + Value(net, v, d.upper());
  return name + " unbounded";
}
}  // namespace

Explanation Explain(const Network& net, const Box& initial, PropagationOptions options) {
  options.record_reasons = false;
  Explanation ex;
  Propagator prop(net, options);
  const int nc = net.num_constraints();
  std::vector<char> enabled(nc, 1);
  auto infeasible = [&](const std::vector<char>& mask) {
    Box b = initial;
    ++ex.propagations;
    return prop.Propagate(b, mask).status == Status::kInfeasible;
  };
  if (!infeasible(enabled)) return ex;
  ex.infeasible = true;
  std::vector<int> requirements;
  for (int c = 0; c < nc; ++c) {
    if (net.constraint(ConstraintId{c}).info.role == ConstraintRole::kRequirement) requirements.push_back(c);
  }
  // Deletion filtering: drop each requirement whose removal keeps the conflict. What remains is
  // minimal: dropping any one of them leaves a network that propagation no longer proves empty.
  for (int r : requirements) {
    enabled[r] = 0;
    if (!infeasible(enabled)) enabled[r] = 1;
  }
  for (int r : requirements) {
    if (enabled[r]) ex.conflict.push_back(r);
  }
  ex.physics_alone = ex.conflict.empty();
  // The chain: propagate the minimal conflict again, recording which constraint narrowed which
  // variable, and trace the way from each conflicting requirement to the constraint where the
  // domain ran empty.
  options.record_reasons = true;
  prop.set_options(options);
  Box box = initial;
  const PropagationReport rep = prop.Propagate(box, enabled);
  ex.empty_constraint = rep.empty_constraint;
  ex.empty_variable = rep.empty_variable;
  auto narrowed = [&](int c, int v) {
    const auto scope = net.ScopeOf(ConstraintId{c});
    for (std::size_t i = 0; i < scope.size(); ++i) {
      if (scope[i] == v) return prop.Narrowed(ConstraintId{c}, static_cast<int>(i));
    }
    return false;
  };
  auto step_for = [&](int c, int v) {
    const BoundReason& lo = prop.lower_reasons()[v];
    const BoundReason& hi = prop.upper_reasons()[v];
    const bool lower = lo.constraint == c || (hi.constraint != c && lo.time >= hi.time);
    return ChainStep{c, v, lower, lower ? box[v].lower() : box[v].upper(), lower ? lo.time : hi.time};
  };
  // Breadth first from the failing constraint: next[c] is the constraint (and via[c] the
  // variable) that the narrowing by c flowed on to, on a shortest way to the failure.
  const int failed = rep.empty_constraint;
  std::vector<int> next(nc, -2), via(nc, -1);
  next[failed] = -1;
  std::vector<int> queue{failed};
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int c = queue[q];
    for (int v : net.ScopeOf(ConstraintId{c})) {
      for (int other : net.ConstraintsOf(VariableId{v})) {
        if (next[other] != -2 || !enabled[other] || !narrowed(other, v)) continue;
        next[other] = c;
        via[other] = v;
        queue.push_back(other);
      }
    }
  }
  std::vector<ChainStep> steps;
  std::vector<char> shown(nc, 0);
  std::vector<std::size_t> path_begin;  // where each requirement's way starts in `steps`
  if (!ex.physics_alone) {
    for (int r : ex.conflict) {
      path_begin.push_back(steps.size());
      for (int c = r; c >= 0 && c != failed && next[c] != -2 && !shown[c]; c = next[c]) {
        shown[c] = 1;
        steps.push_back(step_for(c, via[c]));
      }
    }
  } else {
    // No requirement: the physics narrowed the domains until one ran empty; the last narrowings
    // of the failing constraint's variables, in the order they happened.
    for (int v : net.ScopeOf(ConstraintId{failed})) {
      for (const BoundReason* b : {&prop.lower_reasons()[v], &prop.upper_reasons()[v]}) {
        if (b->constraint < 0 || b->constraint == failed) continue;
        steps.push_back({b->constraint, v, b == &prop.lower_reasons()[v],
                         b == &prop.lower_reasons()[v] ? box[v].lower() : box[v].upper(), b->time});
      }
    }
    std::sort(steps.begin(), steps.end(), [](const ChainStep& a, const ChainStep& b) { return a.time < b.time; });
  }
  ex.chain = steps;

  std::string t;
  if (ex.physics_alone) {
    t += "The model is infeasible even without requirements: the component parameter domains "
         "contradict the physics.\n";
  } else {
    t += ex.conflict.size() == 1 ? "This requirement cannot be met:\n"
                                 : "These requirements cannot be met together:\n";
    for (int c : ex.conflict) t += "  - " + Describe(net, c) + "\n";
    t += ex.conflict.size() == 1 ? "Dropping it removes this conflict.\n"
                                 : "Dropping any one of them removes this conflict.\n";
  }
  t += "How the conflict arises:\n";
  int k = 1;
  for (std::size_t i = 0; i < ex.chain.size(); ++i) {
    const ChainStep& s = ex.chain[i];
    const bool starts = std::find(path_begin.begin(), path_begin.end(), i) != path_begin.end();
    if (starts && ex.conflict.size() > 1) {
      t += "  from requirement '" + Label(net, s.constraint) + "':\n";
    }
    t += "  " + std::to_string(k++) + ". " + Describe(net, s.constraint) + "\n       gives " +
         DomainText(net, s.variable, box[s.variable]) + "\n";
  }
  t += "  " + std::to_string(k) + ". " + Describe(net, failed) + "\n       ";
  if (rep.empty_variable >= 0) {
    t += "leaves no value for " + net.variable(VariableId{rep.empty_variable}).name;
    const Interval d = box[rep.empty_variable];
    if (!IsEmpty(d)) t += " in its narrowed domain, " + DomainText(net, rep.empty_variable, d);
    t += "\n";
  } else {
    // Name the narrowed domains it could not be satisfied in (the ones that were narrowed first).
    std::vector<std::string> domains;
    const auto scope = net.ScopeOf(ConstraintId{failed});
    for (int pass = 0; pass < 2; ++pass) {
      for (int v : scope) {
        const bool moved = prop.lower_reasons()[v].constraint >= 0 || prop.upper_reasons()[v].constraint >= 0;
        if (moved != (pass == 0) || domains.size() >= 6) continue;
        domains.push_back(DomainText(net, v, box[v]));
      }
    }
    t += "cannot hold for any values in the narrowed domains";
    for (std::size_t g = 0; g < domains.size(); ++g) t += (g ? ", " : ": ") + domains[g];
    if (scope.size() > domains.size()) t += ", ...";
    t += "\n";
  }
  ex.text = t;
  return ex;
}

PropagationReport Shave(const Network& net, Box& box, const PropagationOptions& options,
                        const ShavingOptions& shaving) {
  shaving.Validate();
  Propagator prop(net, options);
  PropagationReport total = prop.Propagate(box);
  if (total.status != Status::kFixedPoint) return total;
  int used = 0;
  bool progress = true;
  while (progress && used < shaving.max_propagations) {
    progress = false;
    for (VariableId v : shaving.variables) {
      for (int side = 0; side < 2 && used < shaving.max_propagations; ++side) {
        while (used < shaving.max_propagations) {
          const Interval d = box[v.value];
          const double w = d.upper() - d.lower();
          if (!std::isfinite(w) || w <= 0.0) break;
          const double cut = side == 0 ? d.lower() + w / shaving.slices : d.upper() - w / shaving.slices;
          Box trial = box;
          trial[v.value] = side == 0 ? Interval(d.lower(), cut, true) : Interval(cut, d.upper(), true);
          const PropagationReport r = prop.Propagate(trial);
          ++used;
          total.revisions += r.revisions;
          total.seconds += r.seconds;
          if (r.status != Status::kInfeasible) break;
          box[v.value] = side == 0 ? Interval(cut, d.upper(), true) : Interval(d.lower(), cut, true);
          const PropagationReport after = prop.Propagate(box);
          total.revisions += after.revisions;
          total.seconds += after.seconds;
          progress = true;
          if (after.status != Status::kFixedPoint) {
            total.status = after.status;
            total.message = after.message;
            total.empty_constraint = after.empty_constraint;
            total.empty_variable = after.empty_variable;
            return total;
          }
        }
      }
    }
  }
  total.message = "shaved with " + std::to_string(used) + " trial propagations";
  return total;
}

}  // namespace highlift::icsp
