// Propagation: HC4-revise (forward evaluation, backward projection on the expression DAG) driven
// by an agenda that re-revises only constraints whose variables shrank by more than a relative
// threshold; explanations of infeasibility; optional shaving by bisection.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "highlift/icsp/network.h"

namespace highlift::icsp {

/// Order in which pending constraints are revised.
enum class Schedule : std::uint8_t {
  kFifo,   ///< first in, first out (AC3 style; quadratic on long chains at ratio 0)
  kLifo,   ///< last in, first out (depth first)
  kSweep,  ///< alternating forward/backward sweeps over the constraint order (default): a
           ///< narrowing travels the whole length of a chain in one sweep
};
std::string ToString(Schedule s);
std::optional<Schedule> ScheduleFromString(const std::string& s);

struct PropagationOptions {
  double ratio = 0.0;                       ///< re-revise the neighbours of a variable only when
                                            ///< its width shrank by more than ratio * old width
                                            ///< (0: the exact fixed point, no bound changes left)
  std::int64_t max_revisions = 200'000'000; ///< stop (kStoppedAtLimit) after this many revisions
  double max_seconds = 60.0;                ///< stop (kStoppedAtLimit) after this wall time [s]
  Schedule schedule = Schedule::kSweep;
  bool requeue_self = true;                 ///< put a constraint back on the agenda when it
                                            ///< narrowed its own variables (HC4-revise is not
                                            ///< idempotent); false mimics IBEX's CtcPropag
  bool record_reasons = true;               ///< remember which constraint set each bound (for
                                            ///< explanations); costs two ints per variable
  bool reuse_shared_subexpressions = true;  ///< a subexpression that several constraints share
                                            ///< (one DAG node) is evaluated once per change of
                                            ///< its variables and its value reused by the others;
                                            ///< the fixed point is the same either way
  /// Throws InputError naming the bad option.
  void Validate() const;
};

enum class Status : std::uint8_t {
  kFixedPoint,      ///< nothing more follows (within the ratio); the box encloses all solutions
  kInfeasible,      ///< proved: a domain ran empty, no point satisfies all constraints
  kStoppedAtLimit,  ///< gave up at max_revisions or max_seconds; the box is still sound
};
std::string ToString(Status s);
std::optional<Status> StatusFromString(const std::string& s);

struct PropagationReport {
  Status status = Status::kFixedPoint;
  std::string message;
  std::int64_t revisions = 0;        ///< constraint revisions
  std::int64_t narrowings = 0;       ///< variable domains that shrank
  std::int64_t requeued = 0;         ///< constraints put back on the agenda
  std::int64_t reused_subexpressions = 0;  ///< forward evaluations of shared subexpressions
                                           ///< saved: their kept value was still valid
  int empty_variable = -1;           ///< kInfeasible: the variable whose domain ran empty (-1: an
                                     ///< intermediate expression or the relation itself)
  int empty_constraint = -1;         ///< kInfeasible: the constraint being revised then
  double seconds = 0.0;              ///< wall time of the propagation

  /// One line: "fixed point after 1234 revisions (0.8 ms)".
  std::string BriefReport() const;
  /// Counters and timings as an aligned table.
  std::string FullReport() const;
};

/// Which constraint last moved a bound, and when (revision counter); -1 for the initial domain.
struct BoundReason {
  int constraint = -1;
  std::int64_t time = -1;
};

namespace detail {
class Engine;
}

/// Runs propagation on boxes of one network; reuses its scratch memory between runs.
class Propagator {
 public:
  explicit Propagator(const Network& network, PropagationOptions options = {});
  /// Contracts `box` with all constraints (or only those with enabled[c] != 0 when `enabled` is
  /// not empty). On kInfeasible the box is left as it was when the domain ran empty.
  PropagationReport Propagate(Box& box, const std::vector<char>& enabled = {});
  const PropagationOptions& options() const { return options_; }
  void set_options(const PropagationOptions& o);
  /// After Propagate with record_reasons: reasons of the lower and upper bound of each variable.
  const std::vector<BoundReason>& lower_reasons() const { return lower_reason_; }
  const std::vector<BoundReason>& upper_reasons() const { return upper_reason_; }
  /// After Propagate with record_reasons: whether constraint c ever narrowed the i-th variable of
  /// its scope (Network::ScopeOf(c)[i]) during the run.
  bool Narrowed(ConstraintId c, int i) const {
    return !narrowed_.empty() && narrowed_[network_.constraint(c).vars_begin + i] != 0;
  }

  /// One step of a constraint's compiled evaluation order (operands refer to earlier steps).
  struct Step {
    Op op = Op::kConst;
    int a = -1;      ///< operand step, or the variable index for kVar
    int b = -1;      ///< second operand step
    int aux = 0;     ///< kConst/kPowReal: index into constants; kPowInt: the exponent
    int shared = -1; ///< the node's entry in the shared-subexpression table (-1: one constraint only)
  };
  /// A shared subexpression within one constraint's steps: steps [begin, top] compute the node
  /// of step `top` and nothing else (post-order), so a valid kept value skips all of them.
  struct SharedBlock {
    int begin = 0;
    int top = 0;
    int shared = -1;
  };
  /// Number of distinct subexpressions (non-leaf DAG nodes) that two or more constraints share.
  int num_shared_subexpressions() const { return num_shared_; }

 private:
  friend class detail::Engine;
  void Compile();

  const Network& network_;
  PropagationOptions options_;
  std::vector<Step> tape_;             ///< all constraints' steps, contiguous per constraint
  std::vector<int> tape_begin_;        ///< constraint c uses tape_[tape_begin_[c] .. tape_begin_[c+1])
  std::vector<Interval> constants_;
  int max_steps_ = 0;
  std::vector<SharedBlock> blocks_;    ///< outermost shared subexpressions of each constraint, in
                                       ///< step order; constraint c: blocks_begin_[c] .. [c+1]
  std::vector<int> blocks_begin_;
  int num_shared_ = 0;
  std::vector<int> shared_vars_;       ///< per shared entry: the variables below it, entry e at
  std::vector<int> shared_vars_begin_; ///< shared_vars_[shared_vars_begin_[e] .. [e+1])
  std::vector<BoundReason> lower_reason_, upper_reason_;
  std::vector<char> narrowed_;         ///< per scope entry of every constraint (record_reasons)
};

/// Convenience: Propagator(network, options).Propagate(box).
PropagationReport Propagate(const Network& network, Box& box, const PropagationOptions& options = {});

/// One link of the chain through which a conflict arose: `constraint` moved a bound of
/// `variable` to `bound`.
struct ChainStep {
  int constraint = -1;
  int variable = -1;
  bool lower = true;
  double bound = 0.0;
  std::int64_t time = 0;
};

struct Explanation {
  bool infeasible = false;         ///< the network is proved infeasible
  bool physics_alone = false;      ///< infeasible even without any requirement
  std::vector<int> conflict;       ///< a minimal set of requirement constraints that conflict
                                   ///< (each one is needed; physics constraints are background)
  std::vector<ChainStep> chain;    ///< in causal order, ending where the domain ran empty
  int empty_variable = -1;
  int empty_constraint = -1;
  int propagations = 0;            ///< propagations spent on the search
  std::string text;                ///< the explanation in words
};

/// When propagation of `initial` proves infeasibility, finds a minimal conflicting set of
/// requirements by deletion filtering (physics constraints kept as background) and the chain of
/// constraints and parameters through which the conflict arose. When it does not, returns an
/// Explanation with infeasible == false.
Explanation Explain(const Network& network, const Box& initial, PropagationOptions options = {});

struct ShavingOptions {
  std::vector<VariableId> variables;  ///< variables whose bounds to shave
  int slices = 8;                     ///< a bound slice is 1/slices of the current width
  int max_propagations = 400;         ///< overall limit of trial propagations
  /// Throws InputError naming the bad option.
  void Validate() const;
};

/// Branch and prune on chosen variables: a slice at a bound whose propagation proves it
/// infeasible is cut off, repeatedly. Starts from and keeps a propagated fixed point.
PropagationReport Shave(const Network& network, Box& box, const PropagationOptions& options,
                        const ShavingOptions& shaving);

}  // namespace highlift::icsp
