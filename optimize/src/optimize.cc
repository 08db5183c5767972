// Interval branch and bound over the drive-system constraint network (docs/optimize.md).
#include "highlift/optimize/optimize.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <set>
#include <span>
#include <sstream>

#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/parser.h"
#include "highlift/icsp/propagator.h"
#include "highlift/model/component_model.h"
#include "highlift/model/estimation_laws.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sizing.h"
#include "tube_sizes.h"

namespace highlift::optimize {

using icsp::Box;
using icsp::Interval;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kTubeBoundRounds = 3;  ///< TubeBounds and propagation per box, at most

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

double Mid(const Interval& x) { return 0.5 * (x.lower() + x.upper()); }

/// Interval evaluation of expression nodes over a box (forward only, outward rounded by the
/// interval type): the "is it certain?" test of a constraint at a fixed design.
class Evaluator {
 public:
  explicit Evaluator(const icsp::Network& n) : n_(n), memo_(n.num_nodes()), stamp_(n.num_nodes(), 0) {}
  void Reset(const Box* box) {
    box_ = box;
    ++current_;
  }
  Interval Eval(int node) {
    if (stamp_[node] == current_) return memo_[node];
    const icsp::ExprNode& e = n_.node(icsp::ExprId{node});
    using icsp::Op;
    Interval r;
    switch (e.op) {
      case Op::kVar: r = (*box_)[e.a]; break;
      case Op::kConst: r = e.value; break;
      case Op::kAdd: r = Eval(e.a) + Eval(e.b); break;
      case Op::kSub: r = Eval(e.a) - Eval(e.b); break;
      case Op::kMul: r = Eval(e.a) * Eval(e.b); break;
      case Op::kDiv: r = icsp::Div(Eval(e.a), Eval(e.b)); break;
      case Op::kNeg: r = -Eval(e.a); break;
      case Op::kSqr: r = icsp::Sqr(Eval(e.a)); break;
      case Op::kPowInt: r = icsp::PowInt(Eval(e.a), e.n); break;
      case Op::kPowReal: r = icsp::PowReal(Eval(e.a), e.p); break;
      case Op::kSqrt: r = icsp::Sqrt(Eval(e.a)); break;
      case Op::kExp: r = icsp::Exp(Eval(e.a)); break;
      case Op::kLog: r = icsp::Log(Eval(e.a)); break;
      case Op::kAbs: r = icsp::Abs(Eval(e.a)); break;
      case Op::kMin: r = icsp::Min(Eval(e.a), Eval(e.b)); break;
      case Op::kMax: r = icsp::Max(Eval(e.a), Eval(e.b)); break;
      case Op::kSin: r = icsp::Sin(Eval(e.a)); break;
      case Op::kCos: r = icsp::Cos(Eval(e.a)); break;
    }
    memo_[node] = r;
    stamp_[node] = current_;
    return r;
  }

 private:
  const icsp::Network& n_;
  const Box* box_ = nullptr;
  std::vector<Interval> memo_;
  std::vector<int> stamp_;
  int current_ = 0;
};

/// g OP 0 holds for every point of the box g was evaluated on.
bool Certain(const Interval& g, icsp::Relation r) {
  if (icsp::IsEmpty(g)) return false;
  switch (r) {
    case icsp::Relation::kLessEqual: return g.upper() <= 0.0;
    case icsp::Relation::kGreaterEqual: return g.lower() >= 0.0;
    case icsp::Relation::kEqual: return g.lower() == 0.0 && g.upper() == 0.0;
  }
  return false;
}

/// g OP 0 holds at no point of the box g was evaluated on.
bool Impossible(const Interval& g, icsp::Relation r) {
  if (icsp::IsEmpty(g)) return true;
  switch (r) {
    case icsp::Relation::kLessEqual: return g.lower() > 0.0;
    case icsp::Relation::kGreaterEqual: return g.upper() < 0.0;
    case icsp::Relation::kEqual: return g.lower() > 0.0 || g.upper() < 0.0;
  }
  return false;
}

/// How far g OP 0 is from holding at its worst point of the box g was evaluated on (<= 0: it holds
/// there; g not empty): g's upper end for <=, minus its lower end for >=, the larger for ==.
double WorstExcess(const Interval& g, icsp::Relation r) {
  return r == icsp::Relation::kLessEqual      ? g.upper()
         : r == icsp::Relation::kGreaterEqual ? -g.lower()
                                              : std::max(g.upper(), -g.lower());
}

/// A check's vote between the ends of a parameter's domain, from its worst excess at each: +1 when
/// the lower end is worse (the check comes closer to failing there), -1 the upper, 0 neither.
int VoteLowerWorse(double at_lower, double at_upper) {
  return at_lower > at_upper ? 1 : at_lower < at_upper ? -1 : 0;
}

/// The end of domain d that `votes` (> 0: the lower) calls worse, a hair (1e-6 of the width) inside
/// it: a point where the propagation itself fails (a stiffness of exactly 0 gives 1/0) would cut off
/// designs that are feasible; `otherwise` when the votes tie.
double WorseEnd(const Interval& d, int votes, double otherwise) {
  const double inside = 1e-6 * (d.upper() - d.lower());
  return votes > 0 ? d.lower() + inside : votes < 0 ? d.upper() - inside : otherwise;
}

struct Tolerance {
  double relative, absolute;
  bool Closed(double best, double lower) const {
    return best - lower <= std::max(absolute, relative * std::fabs(best));
  }
};

/// The outcome of one robust feasibility check of a design point.
struct Candidate {
  bool feasible = false;
  double value = kInf;                 ///< objective upper bound over the remaining domains (SI)
  double value_lower = -kInf;
  std::vector<int> failed;             ///< constraints not certain at the point
  std::string reduced_failure;         ///< what Size or AnalysePeaks found, when they failed
  Box box;                             ///< the propagated box (definitions only)
};

/// The right-hand side of a definition written "z == rhs" (root z - rhs, z not in rhs), and z;
/// -1 for any other constraint.
int DefinitionRhs(const icsp::Network& n, int c, int* z) {
  const icsp::Constraint& k = n.constraint(icsp::ConstraintId{c});
  if (k.kind != icsp::Constraint::Kind::kExpression || k.relation != icsp::Relation::kEqual ||
      k.info.role != icsp::ConstraintRole::kPhysics)
    return -1;
  const icsp::ExprNode& root = n.node(icsp::ExprId{k.root});
  if (root.op != icsp::Op::kSub || n.node(icsp::ExprId{root.a}).op != icsp::Op::kVar) return -1;
  const int lhs = n.node(icsp::ExprId{root.a}).a;
  for (int node : n.TopoOf(icsp::ConstraintId{c}))
    if (node != root.a && n.node(icsp::ExprId{node}).op == icsp::Op::kVar && n.node(icsp::ExprId{node}).a == lhs)
      return -1;  // z on both sides
  *z = lhs;
  return root.b;
}

/// The variables an expression node reads.
void VariablesOf(const icsp::Network& n, int node, std::vector<int>& out) {
  const icsp::ExprNode& e = n.node(icsp::ExprId{node});
  if (e.op == icsp::Op::kVar) {
    if (std::find(out.begin(), out.end(), e.a) == out.end()) out.push_back(e.a);
    return;
  }
  if (e.op == icsp::Op::kConst) return;
  if (e.a >= 0) VariablesOf(n, e.a, out);
  if (e.b >= 0) VariablesOf(n, e.b, out);
}

/// A definition y == h(..., m, s, ...) whose factors share arguments: m = f(x) a monotone black
/// box and s == g(x) a definition, some x_i in both (the peak torque w w1 J* of a jam or rupture:
/// the first eigenfrequency w1 falls and J* rises with every inertia of the moving part). Interval
/// evaluation takes w1 at the light corner and J* at the heavy one, which no point reaches (the
/// dependency problem); Optimizer::SharpenProducts encloses h over a partition of the shared x_i.
struct SharedProduct {
  int y = -1, y_rhs = -1;       ///< the variable and the node of h
  int m_constraint = -1;        ///< the monotone constraint of m (its scope: m, then f's arguments)
  int s = -1, s_rhs = -1;       ///< the definition factor and the node of g
  std::vector<int> shared;      ///< the variables that are arguments of f and read by g
  std::vector<int> downstream;  ///< checks that read y through the definitions (sorted)
  std::vector<int> reads;       ///< every variable the bound reads (f's arguments, g's, h's)
  std::vector<Interval> last;   ///< their domains at the last sharpening, and its bound
  double last_upper = kInf;
};

}  // namespace
namespace detail {
namespace {

std::string FirstSizeFailure(const reduced_models::SizingReport& r) {
  for (const auto& s : r.settings)
    if (!s.ok)
      return "size: setting " + s.component + "." + s.parameter + " is outside its rule " + s.rule + " (factor " +
             FormatNumber(s.current_factor, 4) + ")";
  for (const auto& m : r.margins)
    if (m.margin < 0.0)
      return "size: margin of " + m.component + " against its " + m.allowable_name + " is " + FormatNumber(m.margin, 4);
  return "size failed";
}

std::string FirstPeakFailure(const reduced_models::PeakReport& r) {
  for (const auto& w : r.worst)
    if (w.margin < 0.0)
      return "peak: " + w.component + " in '" + w.worst_case + "' carries more than its " + w.allowable_name +
             " (margin " + FormatNumber(w.margin, 4) + ")";
  return "peak failed";
}

}  // namespace

class Optimizer {
 public:
  Optimizer(const Project& project, const Options& options)
      : project_(project), options_(options), dsn_(icsp::BuildDriveSystemNetwork(project)) {}

  /// Design variables, margins, objective, constraint classes, the propagator.
  void Setup();
  Report Run();
  /// A design must beat `value` (SI) to be accepted, and boxes whose bound exceeds it are pruned
  /// (the best design of other part combinations); a pure part choice may have no design variable.
  void CutOff(double value) {
    best_ = value;
    cut_off_ = std::isfinite(value);
  }
  void AllowNoDesignVariable() { allow_no_design_ = true; }
  Candidate Evaluate(const std::vector<double>& x, bool verify);
  const std::vector<std::string>& design_names() const { return design_names_; }
  std::vector<std::pair<double, double>> domains() const {
    std::vector<std::pair<double, double>> out;
    for (int v : design_) out.push_back({initial_[v].lower(), initial_[v].upper()});
    return out;
  }
  std::string FailureText(const Candidate& c) const;
  const std::string& objective_unit() const { return objective_unit_; }

 private:
  icsp::Network& net() { return dsn_.network; }
  void ChooseDesignVariables();
  void AddMargins();
  void AddRelations();
  void AddObjective();
  void ClassifyConstraints();
  void ProbeReducedModels();
  void Consider(const std::vector<double>& x, const Candidate& c);
  void FindSharedProducts();
  bool SharpenProducts(Box& box, const std::vector<int>& failed);
  double UpperByPartition(const SharedProduct& p, const Box& box);
  void LocalSearch(const std::vector<Interval>& d);
  std::string PeakProof(const std::vector<Interval>& d);
  void CoordinateSearch();
  void SetupResize();
  void ResizeTubes();
  bool TubeBounds(Box& box, const std::vector<Box>& others);
  bool TubeContract(Box& box);
  void ChooseOtherPoints(const Box& at);
  Box AtPoint(const std::vector<double>& point) const;
  Box AtIncumbent(const std::vector<double>& point) const;
  void Polish(double lower);
  double ObjectiveAt(const std::vector<double>& x);
  double Shave(Box& box, double lb);
  bool ShaveSlice(Box& box, int v, double slice, const std::vector<char>& enabled = {}, bool tubes = false);
  void ShavingNeighbourhoods();
  void Sensitivities(const Box& root);
  void ChooseScenario();
  std::vector<double> StepTowardsSmaller(const std::vector<double>& x) const;
  void SetupTubeSizes();
  bool ContractTubes(Box& box);
  Candidate Try(const std::vector<double>& x, const std::vector<Interval>& d);
  void FinishTubeSizes(Report& r);
  int ChooseSplit(const std::vector<Interval>& d) const;
  void Finish(Report& r);
  double Seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  Project project_;
  Options options_;
  icsp::DriveSystemNetwork dsn_;
  std::vector<int> design_;             ///< variable indices
  std::vector<std::string> design_names_;
  /// Options::same_value: a parameter that follows design variable `leader` (an index of design_).
  struct Follower {
    int var = -1;
    std::size_t leader = 0;
    std::string name;
  };
  std::vector<Follower> followers_;
  std::vector<std::pair<std::size_t, Interval>> same_domains_;  ///< a group's domain (the intersection)
  /// The design as parameter values (SI) for FixDesign: the design variables and their followers.
  std::vector<std::pair<std::string, double>> DesignValues(const std::vector<double>& x) const {
    std::vector<std::pair<std::string, double>> values;
    for (std::size_t i = 0; i < design_.size(); ++i) values.push_back({design_names_[i], x[i]});
    for (const Follower& f : followers_) values.push_back({f.name, x[f.leader]});
    return values;
  }
  int objective_ = -1, bound_ = -1, bound_constraint_ = -1;
  std::string objective_unit_;
  std::vector<MassTerm> mass_terms_;
  std::vector<int> mass_vars_;          ///< per mass term: its network variable (-1: a constant)
  std::vector<Interval> mass_constants_;
  std::vector<int> terms_;              ///< variables the objective sums (shaved one by one)
  std::vector<std::vector<char>> term_constraints_;  ///< per term: the constraints near it (a mask)
  std::vector<char> definitions_;       ///< enabled mask: the laws that define derived quantities
  std::vector<int> checks_;             ///< constraints a design must satisfy for certain
  std::vector<SharedProduct> products_; ///< definitions the robust check encloses by partition
  Box initial_;
  std::vector<double> sign_, sensitivity_;
  std::vector<double> prefer_;          ///< +1 / -1: the end of its domain the checks favour (0: none)
  std::vector<int> uncertain_;          ///< parameter variables with a domain that are not design variables
  std::vector<double> scenario_;        ///< a point of their domains at which the boxes are contracted
  bool have_scenario_ = false;
  int scenario_generation_ = 0;         ///< incremented whenever scenario_ is chosen again
  std::string scenario_note_;
  std::vector<char> undecided_;  ///< per uncertain parameter: the first vote left it at the middle
  /// The further points of TubeContract (ChooseOtherPoints: the tubes' weak point), each one the
  /// incumbent passes; empty when it is scenario_ itself or the incumbent fails there.
  std::vector<std::vector<double>> other_points_;
  bool verify_size_ = false, verify_peak_ = false;
  std::string verification_note_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::unique_ptr<icsp::Propagator> propagator_;
  std::unique_ptr<icsp::Propagator> shaving_propagator_;  ///< the trials' (Options::shaving_ratio)
  std::unique_ptr<Evaluator> evaluator_;
  std::unique_ptr<TubeConstraint> tubes_;   ///< Options::tube_sizes (null: D and t continuous)
  /// A tube for ResizeTubes, TubeBounds and ChooseOtherPoints: its objective term, its outer
  /// diameter and wall (indices into design_), the laws that give its own derived quantities from
  /// them (variable, node of the law, in the order they follow from one another) and the checks
  /// that read any of those.
  struct Resizable {
    int term = -1;
    std::size_t d = 0, t = 0;
    std::vector<std::pair<int, int>> laws;
    std::vector<int> checks;
    std::vector<std::size_t> own;  ///< the uncertain parameters its laws read (indices into uncertain_)
  };
  std::vector<Resizable> resizable_;
  bool EvalTubeLaws(const Resizable& r, Box& box, const Box* within = nullptr);
  void Excesses(const Box& box, const std::vector<int>& constraints, double missing, std::vector<double>& out);
  // Incumbent.
  bool found_ = false;
  double best_ = kInf;
  bool cut_off_ = false, allow_no_design_ = false;
  std::vector<double> best_x_;
  Candidate best_candidate_;
  Report counters_;
  std::map<std::string, int> rejected_;
  double root_lb_ = -kInf;                  ///< the root box's lower bound (HC4, then shaving)
  std::map<std::string, int> peak_proofs_;  ///< boxes `peak` proved infeasible, by the failing margin
};

void Optimizer::ChooseDesignVariables() {
  std::vector<std::string> names = options_.design;
  for (const Component& c : project_.components)
    for (const auto& [pname, p] : c.parameters)
      if (p.design && std::find(names.begin(), names.end(), c.id + "." + pname) == names.end())
        names.push_back(c.id + "." + pname);
  // Options::same_value: the first name of each group is the design variable, the others follow it.
  std::set<std::string> following;
  for (const std::vector<std::string>& group : options_.same_value) {
    if (std::find(names.begin(), names.end(), group.front()) == names.end()) names.push_back(group.front());
    following.insert(group.begin() + 1, group.end());
  }
  names.erase(std::remove_if(names.begin(), names.end(), [&](const std::string& n) { return following.count(n) > 0; }),
              names.end());
  if (names.empty() && !allow_no_design_)
    throw InputError("no design variable: mark parameters of the project with \"design\": true, or name them with "
                     "--design COMPONENT.PARAMETER (e.g. --design shaft_l1.wall_thickness)");
  for (const std::string& name : names) {
    const auto dot = name.find('.');
    const Component* c = dot == std::string::npos ? nullptr : project_.FindComponent(name.substr(0, dot));
    if (!c)
      throw InputError("design variable '" + name + "': no component '" + name.substr(0, dot == std::string::npos ? name.size() : dot) +
                       "' in the project; name it as COMPONENT.PARAMETER with a component id of the project");
    const std::string pname = name.substr(dot + 1);
    const auto it = c->parameters.find(pname);
    const icsp::VariableId v = net().FindVariable(name);
    if (it == c->parameters.end() || v.value < 0)
      throw InputError("design variable '" + name + "': component '" + c->id + "' gives no parameter '" + pname +
                       "'; give it in the project with \"min\" and \"max\", or choose one of its parameters");
    const Interval dom = net().variable(v).initial;
    if (!std::isfinite(dom.lower()) || !std::isfinite(dom.upper()) || !(dom.upper() > dom.lower()))
      throw InputError("design variable '" + name + "' has no domain to choose from (" +
                       (std::isfinite(dom.lower()) && std::isfinite(dom.upper()) ? "a single value" : "unbounded") +
                       "): give it finite \"min\" and \"max\" in the project");
    if (std::find(design_.begin(), design_.end(), v.value) != design_.end()) continue;
    design_.push_back(v.value);
    design_names_.push_back(name);
  }
  for (const std::vector<std::string>& group : options_.same_value) {
    const std::size_t leader =
        std::find(design_names_.begin(), design_names_.end(), group.front()) - design_names_.begin();
    const icsp::VariableId lv{design_[leader]};
    Interval common = net().variable(lv).initial;
    for (std::size_t k = 1; k < group.size(); ++k) {
      const std::string& name = group[k];
      const auto dot = name.find('.');
      const Component* c = dot == std::string::npos ? nullptr : project_.FindComponent(name.substr(0, dot));
      const icsp::VariableId v = c ? net().FindVariable(name) : icsp::VariableId{-1};
      if (!c || !c->parameters.count(name.substr(dot + 1)) || v.value < 0)
        throw InputError("same value '" + name + "' (group of " + group.front() + "): not a parameter of the project; "
                         "name it as COMPONENT.PARAMETER with a component id and one of its parameters");
      common = icsp::Meet(common, net().variable(v).initial);
      if (icsp::IsEmpty(common) || !(common.upper() > common.lower()))
        throw InputError("same value: the domains of " + group.front() + " and " + name +
                         " have no common range to choose from; give each of the group the same \"min\" and \"max\"");
      followers_.push_back({v.value, leader, name});
      net().AddConstraint(net().Var(v), icsp::Relation::kEqual, net().Var(lv),
                          {"same:" + name, name + " takes the value of the design variable " + group.front() +
                                               " (identical parts, Options::same_value)",
                           icsp::ConstraintRole::kPhysics, name + " == " + group.front()});
    }
    same_domains_.push_back({leader, common});
  }
}

/// Every margin of the network >= 0: limiter settings against their operating torques, the
/// limiter brakes, the tip brakes' holding; a shaft's torque capacity against its drive torque.
void Optimizer::AddMargins() {
  const int n = net().num_variables();
  for (int v = 0; v < n; ++v) {
    const std::string name = net().variable(icsp::VariableId{v}).name;
    static const char* kSuffixes[] = {".margin", ".margin_retract", ".holding_margin", ".brake_margin"};
    for (const char* s : kSuffixes) {
      if (!EndsWith(name, s)) continue;
      net().AddConstraint(net().Var(icsp::VariableId{v}), icsp::Relation::kGreaterEqual, net().Const(0.0),
                          {"margin:" + name, "the setting margin '" + name + "' of `highlift size` is not negative",
                           icsp::ConstraintRole::kRequirement, name + " >= 0"});
    }
    if (EndsWith(name, ".torque_capacity")) {
      const std::string id = name.substr(0, name.size() - std::string(".torque_capacity").size());
      const icsp::VariableId drive = net().FindVariable(id + ".drive_torque");
      if (drive.value >= 0)
        net().AddConstraint(net().Var(icsp::VariableId{v}), icsp::Relation::kGreaterEqual, net().Var(drive),
                            {"margin:" + id + ".torque_capacity",
                             "shaft '" + id + "' carries its drive torque within its torque capacity (`highlift size`)",
                             icsp::ConstraintRole::kRequirement, name + " >= " + id + ".drive_torque"});
    }
  }
}

/// Every parameter relation of the catalogue (a wall within the radius, a lock-out below the end
/// stop, a brake's dynamic torque within its static capacity) that involves a design variable, in
/// validate's semantics: the design value against the other side's nominal value (or against the
/// other design value), so that a design `optimize` returns passes `highlift validate`. A relation
/// whose other side has no nominal holds over that side's whole domain (robustly). A strict
/// relation (a limiter's end stop above its lock-out torques, which the simulation requires) keeps
/// a relative clearance of 1e-9.
void Optimizer::AddRelations() {
  auto is_design = [&](icsp::VariableId v) {
    return v.value >= 0 && std::find(design_.begin(), design_.end(), v.value) != design_.end();
  };
  for (const Component& c : project_.components) {
    const ComponentTypeSpec* type = FindComponentType(c.type);
    if (!type) continue;
    for (const ParameterRelation& r : type->relations) {
      const icsp::VariableId pv = net().FindVariable(c.id + "." + r.parameter);
      const icsp::VariableId bv = net().FindVariable(c.id + "." + r.bound);
      if (!is_design(pv) && !is_design(bv)) continue;  // validate checks the project as given
      auto side = [&](icsp::VariableId v, const std::string& name) -> icsp::ExprId {
        if (is_design(v)) return net().Var(v);
        const auto it = c.parameters.find(name);
        if (it != c.parameters.end() && it->second.nominal) return net().Const(*it->second.nominal);
        return v.value >= 0 ? net().Var(v) : icsp::ExprId{-1};
      };
      const icsp::ExprId lhs = side(pv, r.parameter), rhs = side(bv, r.bound);
      if (lhs.value < 0 || rhs.value < 0) continue;  // no value to relate: validate skips it too
      const double clearance = r.strict ? 1.0 - 1e-9 : 1.0;
      const std::string divisor = r.divisor == 1.0 ? "" : " / " + FormatNumber(r.divisor, 6);
      const std::string text = c.id + "." + r.parameter + (r.strict ? " < " : " <= ") + c.id + "." + r.bound + divisor;
      net().AddConstraint(net().Mul(net().Const(r.divisor), lhs), icsp::Relation::kLessEqual,
                          net().Mul(net().Const(clearance), rhs),
                          {"relation:" + c.id + "." + r.parameter,
                           std::string(type->display_name) + " '" + c.id + "': " + r.parameter + " within " + r.meaning +
                               " (`highlift validate`)",
                           icsp::ConstraintRole::kRequirement, text});
    }
  }
}

void Optimizer::AddObjective() {
  icsp::ExprId expr{-1};
  const std::string& o = options_.objective;
  auto add = [&](icsp::ExprId term) { expr = expr.value < 0 ? term : net().Add(expr, term); };
  if (o == "mass") {
    objective_unit_ = "kg";
    for (const Component& c : project_.components) {
      const icsp::VariableId m = net().FindVariable(c.id + ".mass");
      if (m.value >= 0) {
        add(net().Var(m));
        mass_terms_.push_back({c.id, "tube law m = rho pi (D - t) t L (model::ShaftMass)", 0.0, 0.0});
        mass_vars_.push_back(m.value);
        terms_.push_back(m.value);
        mass_constants_.push_back(Interval(0.0));
        continue;
      }
      const model::ComponentModel* model = model::FindComponentModel(c.type);
      bool counted = false;
      if (model) {
        for (const model::EstimationLaw& law : model->EstimationLaws()) {
          if (!law.derived || law.output != "mass") continue;
          std::vector<model::Interval> in;
          bool ok = true;
          for (const model::LawInput& input : law.inputs) {
            if (input.kind == model::LawInput::Kind::kConstant) {
              in.push_back(input.range);
            } else if (input.kind == model::LawInput::Kind::kParameter) {
              const auto it = c.parameters.find(input.name);
              if (it == c.parameters.end()) { ok = false; break; }
              const Parameter& p = it->second;
              if (std::isfinite(p.domain.lo) && std::isfinite(p.domain.hi)) in.push_back(model::Interval(p.domain.lo, p.domain.hi));
              else if (p.nominal) in.push_back(model::Interval(*p.nominal, *p.nominal));
              else { ok = false; break; }
            } else {
              ok = false;  // a label input (a quantity in a component label): not read here
              break;
            }
          }
          if (!ok) continue;
          const model::Interval m = law.enclosure(in);
          if (!(std::isfinite(m.lo) && std::isfinite(m.hi))) continue;
          const Interval mi(m.lo, m.hi);
          add(net().Const(mi));
          mass_terms_.push_back({c.id, "estimation law: " + law.note + " (over the domains)", m.lo, m.hi});
          mass_vars_.push_back(-1);
          mass_constants_.push_back(mi);
          counted = true;
          break;
        }
      }
      if (!counted && model && (model->roles().actuator || model->roles().drive_unit || model->roles().tip_brake ||
                                model->roles().wing_limiter || model->roles().station_limiter)) {
        mass_terms_.push_back({c.id, "no mass law for type '" + c.type + "' with the project's values: not counted",
                               std::nan(""), std::nan("")});
        mass_vars_.push_back(-1);
        mass_constants_.push_back(Interval(0.0));
      }
    }
    if (expr.value < 0)
      throw InputError("objective 'mass': the project has no component with a mass law (torque shafts with a tube "
                       "geometry and density); minimize 'inertia' or an expression instead");
  } else if (o == "inertia") {
    objective_unit_ = "kg*m^2";
    for (const Component& c : project_.components) {
      const icsp::VariableId j = net().FindVariable(c.id + ".reflected_inertia");
      if (j.value >= 0) {
        add(net().Var(j));
        terms_.push_back(j.value);
      }
    }
    if (expr.value < 0)
      throw InputError("objective 'inertia': the project has no component with an inertia at the PDU; minimize "
                       "'mass' or an expression instead");
  } else {
    expr = icsp::ParseExpression(net(), o, "objective '" + o + "'");
    // The unit of a single quantity is shown; a compound expression is in SI.
    const icsp::VariableId v = net().FindVariable(o);
    if (v.value >= 0) objective_unit_ = net().variable(v).unit;
  }
  objective_ = net().AddVariable("optimize.objective", icsp::Whole(), "", "optimize").value;
  net().AddConstraint(net().Var(icsp::VariableId{objective_}), icsp::Relation::kEqual, expr,
                      {"objective", "the objective '" + o + "'", icsp::ConstraintRole::kPhysics, o});
  bound_ = net().AddVariable("optimize.upper_bound", icsp::Whole(), "", "optimize").value;
  bound_constraint_ = net()
                          .AddConstraint(net().Var(icsp::VariableId{objective_}), icsp::Relation::kLessEqual,
                                         net().Var(icsp::VariableId{bound_}),
                                         {"objective_bound", "the objective does not exceed the best design found",
                                          icsp::ConstraintRole::kPhysics, ""})
                          .value;
}

/// Definitions: the physics equalities and monotone black boxes, which give each derived quantity
/// its law; propagated alone over a box with the design fixed they enclose every derived quantity
/// over the remaining domains. Everything else (requirements, margins, physics inequalities such
/// as parameter relations) must hold for certain.
void Optimizer::ClassifyConstraints() {
  const int m = net().num_constraints();
  definitions_.assign(m, 0);
  for (int c = 0; c < m; ++c) {
    if (c == bound_constraint_) continue;
    const icsp::Constraint& k = net().constraint(icsp::ConstraintId{c});
    const bool definition = k.info.role == icsp::ConstraintRole::kPhysics &&
                            (k.kind == icsp::Constraint::Kind::kMonotone || k.relation == icsp::Relation::kEqual);
    if (definition) definitions_[c] = 1;
    else checks_.push_back(c);
  }
}

void Optimizer::ProbeReducedModels() {
  verify_size_ = options_.verify_size;
  verify_peak_ = options_.verify_peak;
  if (!verify_size_) verification_note_ += "size not verified (verify_size off); ";
  if (!verify_peak_) verification_note_ += "peak not verified (verify_peak off); ";
  if (verify_size_) try {
    reduced_models::SizingOptions so;
    so.intervals = false;
    reduced_models::Size(project_, so);
  } catch (const InputError& e) {
    verify_size_ = false;
    verification_note_ += std::string("size does not apply to this project (") + e.what() + "); ";
  }
  if (verify_peak_) try {
    reduced_models::PeakOptions po;
    po.intervals = false;
    po.rank = false;
    reduced_models::AnalysePeaks(project_, po);
  } catch (const InputError& e) {
    verify_peak_ = false;
    verification_note_ += std::string("peak does not apply to this project (") + e.what() + ")";
  }
  while (!verification_note_.empty() && (verification_note_.back() == ' ' || verification_note_.back() == ';'))
    verification_note_.pop_back();
}

Candidate Optimizer::Evaluate(const std::vector<double>& x, bool verify) {
  ++counters_.candidates;
  Candidate c;
  c.box = initial_;
  for (std::size_t i = 0; i < design_.size(); ++i) c.box[design_[i]] = Interval(x[i]);
  c.box[bound_] = icsp::Whole();
  const icsp::PropagationReport rep = propagator_->Propagate(c.box, definitions_);
  if (rep.status == icsp::Status::kInfeasible) {
    c.failed.push_back(rep.empty_constraint);
    return c;
  }
  auto check = [&] {
    c.failed.clear();
    evaluator_->Reset(&c.box);
    for (int k : checks_) {
      const icsp::Constraint& con = net().constraint(icsp::ConstraintId{k});
      if (con.kind != icsp::Constraint::Kind::kExpression) continue;
      if (!Certain(evaluator_->Eval(con.root), con.relation)) c.failed.push_back(k);
    }
  };
  check();
  // A requirement that is not certain may only look so because of the dependency problem in a
  // product law: enclose those again by partition, propagate the narrowed values, check again.
  // First only the laws behind the first failing check: when it still fails, so does x, and the
  // others are not worth sharpening. Nor is a design that cannot beat the incumbent.
  if (!c.failed.empty() && options_.dependency_splits > 0 && !products_.empty() &&
      !(c.box[objective_].lower() >= best_)) {
    for (int stage = 0; stage < 2 && !c.failed.empty(); ++stage) {
      const std::vector<int> target = stage == 0 ? std::vector<int>{c.failed.front()} : c.failed;
      if (!SharpenProducts(c.box, target)) break;
      const icsp::PropagationReport again = propagator_->Propagate(c.box, definitions_);
      if (again.status == icsp::Status::kInfeasible) {
        c.failed.assign(1, again.empty_constraint);
        return c;
      }
      check();
      if (std::find(c.failed.begin(), c.failed.end(), target.front()) != c.failed.end()) break;
    }
  }
  const Interval obj = c.box[objective_];
  c.value = obj.upper();
  c.value_lower = obj.lower();
  if (!c.failed.empty() || !std::isfinite(c.value)) return c;
  if (verify && (verify_size_ || verify_peak_)) {
    ++counters_.reduced_model_checks;
    const Project p = FixDesign(project_, DesignValues(x));
    if (verify_size_) {
      reduced_models::SizingOptions so;
      const reduced_models::SizingReport sr = reduced_models::Size(p, so);
      if (!sr.ok()) {
        c.reduced_failure = FirstSizeFailure(sr);
        return c;
      }
    }
    if (verify_peak_) {
      reduced_models::PeakOptions po;
      po.rank = false;
      const reduced_models::PeakReport pr = reduced_models::AnalysePeaks(p, po);
      if (!pr.ok()) {
        c.reduced_failure = FirstPeakFailure(pr);
        return c;
      }
    }
  }
  c.feasible = true;
  return c;
}

void Optimizer::FindSharedProducts() {
  const icsp::Network& n = net();
  for (int c = 0; c < n.num_constraints(); ++c) {
    const icsp::Constraint& k = n.constraint(icsp::ConstraintId{c});
    if (!definitions_[c] || k.kind != icsp::Constraint::Kind::kMonotone) continue;
    const auto scope = n.ScopeOf(icsp::ConstraintId{c});
    const int m = scope[0];
    for (int law : n.ConstraintsOf(icsp::VariableId{m})) {
      int y = -1;
      const int h = law == c || !definitions_[law] ? -1 : DefinitionRhs(n, law, &y);
      if (h < 0 || y == m) continue;
      for (int s : n.ScopeOf(icsp::ConstraintId{law})) {
        if (s == y || s == m) continue;
        SharedProduct p;
        for (int def : n.ConstraintsOf(icsp::VariableId{s})) {
          int z = -1;
          const int g = definitions_[def] ? DefinitionRhs(n, def, &z) : -1;
          if (g < 0 || z != s) continue;
          std::vector<int> read;
          VariablesOf(n, g, read);
          for (int v : read)
            if (v != m && std::find(scope.begin() + 1, scope.end(), v) != scope.end()) p.shared.push_back(v);
          if (p.shared.empty()) continue;
          p.y = y, p.y_rhs = h, p.m_constraint = c, p.s = s, p.s_rhs = g;
          p.reads.assign(scope.begin(), scope.end());
          VariablesOf(n, g, p.reads);
          VariablesOf(n, h, p.reads);
          break;
        }
        if (p.y < 0) continue;
        // The checks y reaches forward through the definitions (a definition's left side, or a
        // monotone box's value, from the variables it reads).
        std::vector<char> reached(n.num_variables(), 0);
        std::vector<int> frontier = {y};
        reached[y] = 1;
        while (!frontier.empty()) {
          const int v = frontier.back();
          frontier.pop_back();
          for (int d : n.ConstraintsOf(icsp::VariableId{v})) {
            if (!definitions_[d]) continue;
            int z = -1;
            if (n.constraint(icsp::ConstraintId{d}).kind == icsp::Constraint::Kind::kMonotone)
              z = n.ScopeOf(icsp::ConstraintId{d})[0];
            else if (DefinitionRhs(n, d, &z) < 0)
              continue;
            if (z != v && !reached[z]) reached[z] = 1, frontier.push_back(z);
          }
        }
        for (int k2 : checks_) {
          const auto sc = n.ScopeOf(icsp::ConstraintId{k2});
          if (std::any_of(sc.begin(), sc.end(), [&](int v) { return reached[v] != 0; })) p.downstream.push_back(k2);
        }
        if (!p.downstream.empty()) products_.push_back(std::move(p));
        break;
      }
    }
  }
}

/// Branch and bound on the upper end of each product law's value whose checks failed: the box of
/// its shared arguments is bisected (the part with the largest bound, at the argument that moves
/// g the most), each part bounded by the black box's upper corner and g and h over the part. The
/// largest bound over the parts encloses every value y takes in the box (a partition; each part's
/// bound is an interval enclosure), so intersecting y with it is sound. True when y narrowed.
bool Optimizer::SharpenProducts(Box& box, const std::vector<int>& failed) {
  if (options_.dependency_splits <= 0) return false;
  bool narrowed = false;
  for (SharedProduct& p : products_) {
    if (std::none_of(failed.begin(), failed.end(),
                     [&](int k) { return std::binary_search(p.downstream.begin(), p.downstream.end(), k); }))
      continue;
    // The same domains as last time (a line search moves other variables): the same bound.
    bool same = p.last.size() == p.reads.size();
    for (std::size_t i = 0; same && i < p.reads.size(); ++i) {
      const Interval& a = box[p.reads[i]];
      same = a.lower() == p.last[i].lower() && a.upper() == p.last[i].upper();
    }
    if (!same) {
      p.last.clear();
      for (int v : p.reads) p.last.push_back(box[v]);
      p.last_upper = UpperByPartition(p, box);
    }
    if (p.last_upper < box[p.y].upper()) {
      box[p.y] = icsp::Meet(box[p.y], icsp::Make(-kInf, p.last_upper));
      narrowed = true;
    }
  }
  return narrowed;
}

double Optimizer::UpperByPartition(const SharedProduct& p, const Box& box) {
  const icsp::Network& n = net();
  const icsp::Constraint& mc = n.constraint(icsp::ConstraintId{p.m_constraint});
  const icsp::MonotoneFunction& f = n.monotone(mc.monotone);
  const auto scope = n.ScopeOf(icsp::ConstraintId{p.m_constraint});
  const int m = scope[0];
  const std::size_t ns = p.shared.size();
  Box sub = box;
  std::vector<double> x(scope.size() - 1);
  // The upper bound of y over the part where the shared arguments take `d` (-inf: no point).
  auto bound = [&](const std::vector<Interval>& d) {
    for (std::size_t j = 0; j < ns; ++j) sub[p.shared[j]] = d[j];
    for (std::size_t i = 0; i + 1 < scope.size(); ++i) {
      const Interval& a = sub[scope[i + 1]];
      x[i] = f.monotonicity[i] == icsp::Monotonicity::kIncreasing ? a.upper() : a.lower();
      if (!std::isfinite(x[i])) return kInf;
    }
    double fhi = f.f(std::span<const double>(x.data(), x.size()));
    if (std::isnan(fhi)) return kInf;
    fhi = std::nextafter(fhi + f.relative_error * std::fabs(fhi), kInf);  // as the propagator widens
    sub[m] = icsp::Meet(box[m], icsp::Make(-kInf, fhi));
    if (icsp::IsEmpty(sub[m])) return -kInf;
    evaluator_->Reset(&sub);
    sub[p.s] = icsp::Meet(box[p.s], evaluator_->Eval(p.s_rhs));
    if (icsp::IsEmpty(sub[p.s])) return -kInf;
    evaluator_->Reset(&sub);
    const Interval yv = evaluator_->Eval(p.y_rhs);
    return icsp::IsEmpty(yv) ? -kInf : yv.upper();
  };
  // How much each shared argument moves g per unit of its width (over the whole box, the others
  // at their lower ends; exact for a sum such as J*): a part is bisected at the argument whose
  // width times this is largest.
  std::vector<double> weight(ns, 0.0);
  for (std::size_t j = 0; j < ns; ++j) {
    const Interval& dj = box[p.shared[j]];
    if (!(dj.upper() > dj.lower())) continue;
    for (std::size_t i = 0; i < ns; ++i) sub[p.shared[i]] = i == j ? dj : Interval(box[p.shared[i]].lower());
    evaluator_->Reset(&sub);
    const Interval g = evaluator_->Eval(p.s_rhs);
    if (!icsp::IsEmpty(g)) weight[j] = (g.upper() - g.lower()) / (dj.upper() - dj.lower());
  }
  auto widest = [&](const std::vector<Interval>& d) {
    int best = -1;
    double score = 0.0;
    for (std::size_t j = 0; j < ns; ++j) {
      if (!(d[j].upper() > d[j].lower())) continue;
      const double w = (weight[j] > 0.0 ? weight[j] : 1e-300) * (d[j].upper() - d[j].lower());
      if (w > score || best < 0) score = w, best = static_cast<int>(j);
    }
    return best;
  };
  struct Part {
    double upper;
    std::vector<Interval> d;
    bool operator<(const Part& o) const { return upper < o.upper; }
  };
  std::priority_queue<Part> parts;
  std::vector<Interval> whole;
  for (int v : p.shared) whole.push_back(box[v]);
  parts.push({bound(whole), whole});
  for (int split = 0; split < options_.dependency_splits && !parts.empty(); ++split) {
    if (!std::isfinite(parts.top().upper)) break;
    const int j = widest(parts.top().d);
    if (j < 0) break;
    Part top = parts.top();
    parts.pop();
    const double mid = Mid(top.d[j]);
    std::vector<Interval> lo = top.d, hi = top.d;
    lo[j] = icsp::Make(top.d[j].lower(), mid);
    hi[j] = icsp::Make(mid, top.d[j].upper());
    for (auto* d : {&lo, &hi}) {
      const double u = bound(*d);
      if (u > -kInf) parts.push({u, std::move(*d)});
    }
  }
  const double upper = parts.empty() ? -kInf : parts.top().upper;
  return upper;
}

void Optimizer::Consider(const std::vector<double>& x, const Candidate& c) {
  if (!c.feasible) {
    ++rejected_[FailureText(c)];
    return;
  }
  if (!(c.value < best_)) return;
  best_ = c.value;
  best_x_ = x;
  best_candidate_ = c;
  found_ = true;
  ++counters_.improvements;
}

/// The objective's response to each design variable at the middle of the domains (definitions
/// only): its sign gives the direction of the local search, its size the bisection priority. For
/// a variable the objective does not read, the end of its domain in `root` (the contracted root
/// box) that the checks favour, if any (prefer_).
void Optimizer::Sensitivities(const Box& root) {
  const std::size_t n = design_.size();
  sign_.assign(n, 0.0);
  sensitivity_.assign(n, 0.0);
  std::vector<double> mid(n);
  for (std::size_t i = 0; i < n; ++i) mid[i] = Mid(initial_[design_[i]]);
  auto value = [&](const std::vector<double>& x) {
    Box box = initial_;
    for (std::size_t i = 0; i < n; ++i) box[design_[i]] = Interval(x[i]);
    if (propagator_->Propagate(box, definitions_).status == icsp::Status::kInfeasible) return std::nan("");
    return Mid(box[objective_]);
  };
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> lo = mid, hi = mid;
    lo[i] = initial_[design_[i]].lower();
    hi[i] = initial_[design_[i]].upper();
    const double d = value(hi) - value(lo);
    if (std::isfinite(d) && d != 0.0) {
      sign_[i] = d > 0 ? 1.0 : -1.0;
      sensitivity_[i] = std::fabs(d);
    }
  }
  // A variable the objective does not read (an actuator ratio, a setting) may still move it through
  // the constraints: a larger actuator ratio lowers every torque on the drive line, so more designs
  // meet the requirements, up to the extension time. When the checks it moves nearly all favour
  // one end of its domain in the root box (at the box's middle, at least nine in ten of them
  // closer to holding at that end), the searches treat that end as the light one and, since the
  // objective does not mind, as the safe one too (LocalSearch): a box's middle at the ratio's
  // middle fails the limiter margins that its upper end meets. Only where the searches look
  // depends on it, not the certificate.
  prefer_.assign(n, 0.0);
  std::vector<double> centre(n);
  for (std::size_t i = 0; i < n; ++i) centre[i] = Mid(root[design_[i]]);
  auto slack = [&](const std::vector<double>& x, std::vector<double>& out) {
    Box box = initial_;
    for (std::size_t k = 0; k < n; ++k) box[design_[k]] = Interval(x[k]);
    box[bound_] = icsp::Whole();
    if (propagator_->Propagate(box, definitions_).status == icsp::Status::kInfeasible)
      out.assign(checks_.size(), kInf);
    else
      Excesses(box, checks_, kInf, out);
  };
  std::vector<double> at_lo, at_hi;
  for (std::size_t i = 0; i < n; ++i) {
    const Interval d = root[design_[i]];
    if (sign_[i] != 0.0 || !(d.upper() > d.lower())) continue;
    std::vector<double> x = centre;
    x[i] = d.lower();
    slack(x, at_lo);
    x[i] = d.upper();
    slack(x, at_hi);
    int lo_better = 0, hi_better = 0;
    for (std::size_t a = 0; a < checks_.size(); ++a) {
      const double u = at_lo[a], v = at_hi[a];
      if (u == v || !(std::fabs(u - v) > 1e-9 * std::max(std::fabs(u), std::fabs(v)))) continue;
      (u < v ? lo_better : hi_better) += 1;
    }
    if (hi_better >= 9 * lo_better && hi_better > 0) prefer_[i] = 1.0;
    else if (lo_better >= 9 * hi_better && lo_better > 0) prefer_[i] = -1.0;
    sign_[i] = -prefer_[i];  // the objective "likes" the end the checks favour
  }
}

/// Largest width (relative to the domain) x objective sensitivity; a variable the objective does
/// not move (a setting) still gets a small weight, so feasibility can split it.
int Optimizer::ChooseSplit(const std::vector<Interval>& d) const {
  double smax = 0.0;
  for (double s : sensitivity_) smax = std::max(smax, s);
  int best = -1;
  double score = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const Interval dom = initial_[design_[i]];
    const double rel = (d[i].upper() - d[i].lower()) / (dom.upper() - dom.lower());
    if (!(rel > 1e-13)) continue;
    const double weight = (smax > 0.0 ? sensitivity_[i] / smax : 0.0) + 0.05;
    if (rel * weight > score) {
      score = rel * weight;
      best = static_cast<int>(i);
    }
  }
  return best;
}

/// One step of 1e-4 of each domain from x towards a smaller objective.
std::vector<double> Optimizer::StepTowardsSmaller(const std::vector<double>& x) const {
  std::vector<double> step = x;
  for (std::size_t i = 0; i < design_.size(); ++i) {
    const double w = initial_[design_[i]].upper() - initial_[design_[i]].lower();
    step[i] = std::clamp(x[i] - sign_[i] * 1e-4 * w, initial_[design_[i]].lower(), initial_[design_[i]].upper());
  }
  return step;
}

/// The worst case of the uncertain parameters for the constraints that limit the incumbent: each
/// parameter at the end of its domain where those constraints come closest to failing (by a vote
/// over them), or at its middle when it does not move them. Any point of the domains gives a sound
/// relaxation (a robustly feasible design is feasible at every point, and its worst-case objective
/// is at least the objective there), so the boxes are contracted at this point: the worse the
/// point, the tighter the lower bound. Each parameter is voted with the others at the middle of
/// their domains: over their whole domains the interval enclosure decouples what shares them (a
/// jam's w w1 J*: its eigenfrequency at the light corner, J* at the heavy one), so an inertia that
/// raises a jam load at every point looked better at its upper end and was put at its lower.
/// Then the further points of the tubes' bounds (ChooseOtherPoints).
void Optimizer::ChooseScenario() {
  const Candidate probe = Evaluate(StepTowardsSmaller(best_x_), false);
  std::vector<int> active;
  for (int k : probe.failed)
    if (k >= 0 && net().constraint(icsp::ConstraintId{k}).kind == icsp::Constraint::Kind::kExpression) active.push_back(k);
  // A parameter that none of the active constraints reads (or that they pull both ways alike) is
  // put where the other checks want it (the incumbent's slack ones: a tube whose requirement is
  // not yet tight at the incumbent still binds nearby designs), not at the middle of its domain.
  const std::size_t num_active = active.size();
  for (int k : checks_)
    if (net().constraint(icsp::ConstraintId{k}).kind == icsp::Constraint::Kind::kExpression &&
        std::find(active.begin(), active.begin() + num_active, k) == active.begin() + num_active)
      active.push_back(k);
  Box base = initial_;
  for (std::size_t i = 0; i < design_.size(); ++i) base[design_[i]] = Interval(best_x_[i]);
  base[bound_] = icsp::Whole();
  for (int v : uncertain_) base[v] = Interval(Mid(initial_[v]));
  auto worst = [&](const Box& box, std::vector<double>& out) { Excesses(box, active, -kInf, out); };
  scenario_.assign(uncertain_.size(), 0.0);
  undecided_.assign(uncertain_.size(), 0);
  std::vector<double> at_lo, at_hi;
  for (std::size_t j = 0; j < uncertain_.size(); ++j) {
    const Interval d = initial_[uncertain_[j]];
    Box lo = base, hi = base;
    lo[uncertain_[j]] = Interval(d.lower());
    hi[uncertain_[j]] = Interval(d.upper());
    const bool lo_ok = propagator_->Propagate(lo, definitions_).status != icsp::Status::kInfeasible;
    const bool hi_ok = propagator_->Propagate(hi, definitions_).status != icsp::Status::kInfeasible;
    int votes = 0;  // > 0: the lower end is worse
    if (lo_ok && hi_ok) {
      worst(lo, at_lo);
      worst(hi, at_hi);
      int others = 0;
      for (std::size_t a = 0; a < active.size(); ++a)
        (a < num_active ? votes : others) += VoteLowerWorse(at_lo[a], at_hi[a]);
      if (votes == 0) votes = others;
    } else {
      votes = lo_ok ? -1 : hi_ok ? 1 : 0;
    }
    scenario_[j] = WorseEnd(d, votes, Mid(d));
    undecided_[j] = votes == 0;
  }
  // The point is used only when the incumbent passes the whole network there.
  Box check = AtIncumbent(scenario_);
  have_scenario_ = propagator_->Propagate(check).status != icsp::Status::kInfeasible;
  ++scenario_generation_;
  other_points_.clear();
  if (have_scenario_) ChooseOtherPoints(check);
  if (!have_scenario_) scenario_note_ = "the worst-case point of the uncertain parameters was not used (the network "
                                        "rejects the best design there); the bound is the existential relaxation's";
}

/// The further points of TubeContract: a robust design meets every check at every point of the
/// uncertain domains, so a lower bound may require it at several. The first (scenario_) is voted
/// by the active checks, each parameter for the end most of them find worse; so a parameter that
/// raises the loads of many tubes goes where the loads are highest even where it weakens a tube
/// itself (a tube's shear modulus: its stiffness raises the jam loads through it, its buckling
/// stress grows with E = 2 G (1 + nu)). The weak point moves each resizable tube's own uncertain
/// parameters (its allowable, shear modulus, Poisson's ratio, ...) to the end where its own checks
/// are worse at the incumbent (`at`: the network propagated there at scenario_; the tube's laws
/// evaluated again, the loads held), by the votes of those checks; it is used when the incumbent
/// passes the network there. A parameter the first vote left undecided (at the middle of its
/// domain: no check moved with it there, e.g. the allowable shear stress where the buckling stress
/// governs min(tau_allow, tau_cr) at the middle point) goes to its weak end in the first point too.
/// Tried and not kept (docs/performance.md): a point of the parameters the active checks voted
/// both ways on, and the tubes' own points (each tube's checks' votes) in groups.
void Optimizer::ChooseOtherPoints(const Box& at) {
  const std::size_t n = uncertain_.size();
  auto passes = [&](const std::vector<double>& point) {
    Box check = AtIncumbent(point);
    return propagator_->Propagate(check).status != icsp::Status::kInfeasible;
  };
  std::vector<double> weak = scenario_;
  Box work = at;
  for (const Resizable& r : resizable_) {
    for (std::size_t j : r.own) {
      const Interval d = initial_[uncertain_[j]];
      std::vector<double> excess[2];
      for (int end = 0; end < 2; ++end) {
        work[uncertain_[j]] = Interval(end == 0 ? d.lower() : d.upper());
        EvalTubeLaws(r, work);
        Excesses(work, r.checks, kInf, excess[end]);
      }
      work[uncertain_[j]] = at[uncertain_[j]];
      for (const auto& [z, rhs] : r.laws) work[z] = at[z];
      int votes = 0;  // > 0: the lower end is worse
      for (std::size_t a = 0; a < excess[0].size(); ++a) votes += VoteLowerWorse(excess[0][a], excess[1][a]);
      weak[j] = WorseEnd(d, votes, weak[j]);
    }
  }
  std::vector<double> first = scenario_;
  for (std::size_t j = 0; j < n; ++j)
    if (undecided_[j]) first[j] = weak[j];
  if (first != scenario_ && passes(first)) scenario_ = first;
  if (weak != scenario_ && passes(weak)) other_points_.push_back(weak);
}

/// initial_ with the uncertain parameters at `point` (a value each, in the order of uncertain_).
Box Optimizer::AtPoint(const std::vector<double>& point) const {
  Box box = initial_;
  for (std::size_t j = 0; j < uncertain_.size(); ++j) box[uncertain_[j]] = Interval(point[j]);
  return box;
}

/// The network's box at the incumbent and `point`, the objective unbounded.
Box Optimizer::AtIncumbent(const std::vector<double>& point) const {
  Box box = AtPoint(point);
  for (std::size_t i = 0; i < design_.size(); ++i) box[design_[i]] = Interval(best_x_[i]);
  box[bound_] = icsp::Whole();
  return box;
}

/// `highlift peak` over a whole box of designs (AnalysePeaks' enclosures over the box and the
/// remaining domains): the first component whose load exceeds its allowable at every point of the
/// box (an upper bound of its margin below 0: PeakReport's margin_max), named with its case and
/// numbers; "" when no margin fails for certain. A box it names holds no design that passes peak.
std::string Optimizer::PeakProof(const std::vector<Interval>& d) {
  if (!verify_peak_) return "";
  Project p = project_;
  std::vector<std::pair<std::string, Interval>> ranges;  // the design variables, then their followers
  for (std::size_t i = 0; i < design_.size(); ++i) ranges.push_back({design_names_[i], d[i]});
  for (const Follower& f : followers_) ranges.push_back({f.name, d[f.leader]});
  for (const auto& [name, range] : ranges) {
    const auto dot = name.find('.');
    Parameter& par = p.FindComponent(name.substr(0, dot))->parameters[name.substr(dot + 1)];
    par.domain = {range.lower(), range.upper()};
    par.nominal = Mid(range);
  }
  reduced_models::PeakOptions po;
  po.rank = false;
  ++counters_.peak_checks;
  const reduced_models::PeakReport pr = reduced_models::AnalysePeaks(p, po);
  for (const reduced_models::ComponentPeak& w : pr.worst)
    if (w.margin_max < 0.0)
      return "peak: " + w.component + " in '" + w.certain_case + "' carries at least " +
             FormatNumber(w.local_torque_certain, 4) + " N*m, more than its " + w.allowable_name + " of at most " +
             FormatNumber(w.allowable_max, 4) + " N*m (margin at most " + FormatNumber(w.margin_max, 3) + ")";
  return "";
}

/// Polishes the incumbent one design variable at a time: a bisection from its value towards the
/// end of its whole domain the objective likes (the others fixed), keeping the farthest robustly
/// feasible point; the variables the objective moves most first. The line search inside boxes
/// moves every variable together, so one binding variable stops all of them; this frees the
/// others (run after the 1st, 2nd, 4th, ... improvement: n x line_search_steps evaluations).
void Optimizer::CoordinateSearch() {
  std::vector<std::size_t> order(design_.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  // The variables the objective does not read but the checks favour at one end (prefer_: an
  // actuator ratio) first: moved towards that end, they free the others.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return (prefer_[a] != 0.0) != (prefer_[b] != 0.0) ? prefer_[a] != 0.0 : sensitivity_[a] > sensitivity_[b];
  });
  std::vector<Interval> whole;
  for (int v : design_) whole.push_back(initial_[v]);
  for (std::size_t i : order) {
    if (sign_[i] == 0.0 || Seconds() > options_.max_seconds) continue;
    const Interval dom = initial_[design_[i]];
    const double from = best_x_[i], to = sign_[i] > 0 ? dom.lower() : dom.upper();
    if (from == to) continue;
    // Such a variable does not change the objective, so a feasible point of it is taken even when
    // it is no lighter (a tie); twice the steps, since its end is usually a requirement's bound
    // (the extension time), not the domain's. Evaluated as given: it is no tube's D or t (those
    // the objective reads), so with --tube-sizes the incumbent stays made of sizes.
    const bool tie = prefer_[i] != 0.0;
    double lo = 0.0, hi = 1.0;
    for (int s = 0; s <= (tie ? 2 : 1) * options_.line_search_steps; ++s) {
      const double t = s == 0 ? 1.0 : 0.5 * (lo + hi);
      std::vector<double> x = best_x_;
      const double base = from;  // best_x_[i] may have moved: keep the segment of this variable
      x[i] = base + t * (to - base);
      Candidate c = tie ? Evaluate(x, true) : Try(x, whole);
      if (tie) {
        Consider(x, c);
        if (c.feasible && c.value <= best_) {
          best_ = c.value;
          best_x_ = x;
          best_candidate_ = c;
        }
      }
      if (c.feasible) {
        if (s == 0) break;  // the end itself is feasible
        lo = t;
      } else {
        hi = t;
      }
    }
  }
}

/// The tubes ResizeTubes can resize and TubeBounds bounds: an objective term that is a torque shaft's own derived
/// quantity (its mass) with both its outer diameter and its wall design variables (not with
/// Options::tube_sizes: the sizes are discrete).
void Optimizer::SetupResize() {
  resizable_.clear();
  if (tubes_ || (options_.resize_iterations <= 0 && options_.tube_bound_splits <= 0)) return;
  const int nc = net().num_constraints();
  for (int term : terms_) {
    const std::string& name = net().variable(icsp::VariableId{term}).name;
    const std::size_t dot = name.rfind('.');
    if (dot == std::string::npos) continue;
    const std::string prefix = name.substr(0, dot + 1);
    const int D = net().FindVariable(prefix + "outer_diameter").value;
    const int t = net().FindVariable(prefix + "wall_thickness").value;
    const auto at = [&](int v) { return std::find(design_.begin(), design_.end(), v) - design_.begin(); };
    if (D < 0 || t < 0 || at(D) == static_cast<long>(design_.size()) || at(t) == static_cast<long>(design_.size()))
      continue;
    Resizable r;
    r.term = term;
    r.d = static_cast<std::size_t>(at(D));
    r.t = static_cast<std::size_t>(at(t));
    // The tube's own laws: definitions z == h whose z and every variable h reads are the tube's
    // (prefix), h reading D, t or a quantity already derived from them; the first law of each z.
    std::vector<char> derived(net().num_variables(), 0);
    derived[D] = derived[t] = 1;
    auto own = [&](int v) { return net().variable(icsp::VariableId{v}).name.rfind(prefix, 0) == 0; };
    for (bool more = true; more;) {
      more = false;
      for (int c = 0; c < nc; ++c) {
        if (!definitions_[c]) continue;
        int z = -1;
        const int rhs = DefinitionRhs(net(), c, &z);
        if (rhs < 0 || derived[z] || !own(z)) continue;
        std::vector<int> reads;
        VariablesOf(net(), rhs, reads);
        if (!std::all_of(reads.begin(), reads.end(), own) ||
            std::none_of(reads.begin(), reads.end(), [&](int v) { return derived[v] != 0; }))
          continue;
        r.laws.push_back({z, rhs});
        derived[z] = 1;
        more = true;
        for (int v : reads)
          for (std::size_t j = 0; j < uncertain_.size(); ++j)
            if (uncertain_[j] == v && std::find(r.own.begin(), r.own.end(), j) == r.own.end()) r.own.push_back(j);
      }
    }
    if (!derived[term]) continue;  // the term is not the tube's own law of D and t
    for (int k : checks_) {
      const icsp::Constraint& con = net().constraint(icsp::ConstraintId{k});
      if (con.kind != icsp::Constraint::Kind::kExpression) continue;
      const auto scope = net().ScopeOf(icsp::ConstraintId{k});
      if (std::any_of(scope.begin(), scope.end(), [&](int v) { return derived[v] != 0; })) r.checks.push_back(k);
    }
    resizable_.push_back(std::move(r));
  }
}

/// Resizing the incumbent's tubes (Options::resize_iterations; docs/optimize.md, Method 3): a
/// fully stressed design step. With the loads of a design held at their enclosures over the
/// remaining domains (its robust check's box), each tube's lightest outer diameter and wall
/// within their domains is found alone: for walls on a geometric grid, the least diameter at
/// which every check that reads the tube holds for certain (its laws evaluated at the point, the
/// loads as they are), then the lightest of those. The tubes move together; the new design is
/// checked as every candidate (Try), and as stiffer or softer tubes move the loads, the next
/// iteration resizes for the new design's loads (a design that fails is not kept, only its
/// loads). The branch and bound's searches move one variable, or one direction, at a time; this
/// moves a tube along its capacity requirement (a thinner wall at a larger diameter), and every
/// tube at once.
void Optimizer::ResizeTubes() {
  if (resizable_.empty() || !found_) return;
  std::vector<Interval> whole;
  for (int v : design_) whole.push_back(initial_[v]);
  std::vector<double> x = best_x_;
  Box loads = best_candidate_.box;
  const int kWalls = 24, kSteps = 40;
  for (int it = 0; it < options_.resize_iterations && Seconds() < options_.max_seconds; ++it) {
    std::vector<double> next = x;
    bool moved = false;
    for (const Resizable& r : resizable_) {
      const int D = design_[r.d], t = design_[r.t];
      const Box keep = loads;  // restored below: the trial points change the tube's own quantities
      auto at = [&](double d, double w, bool* ok) {
        loads[D] = Interval(d);
        loads[t] = Interval(w);
        EvalTubeLaws(r, loads);
        *ok = true;
        for (int k : r.checks) {
          const icsp::Constraint& con = net().constraint(icsp::ConstraintId{k});
          if (!Certain(evaluator_->Eval(con.root), con.relation)) {
            *ok = false;
            break;
          }
        }
        return loads[r.term].upper();
      };
      const Interval dd = initial_[D], tt = initial_[t];
      // The least diameter with every check certain at wall w, and the tube's mass there (+inf:
      // none within the domain).
      auto least = [&](double w, double* d) {
        bool ok = false;
        at(dd.upper(), w, &ok);
        if (!ok) return kInf;
        double lo = dd.lower(), hi = dd.upper();
        at(lo, w, &ok);
        if (ok) hi = lo;
        for (int s = 0; s < kSteps && !ok; ++s) {
          const double m = 0.5 * (lo + hi);
          bool okm = false;
          at(m, w, &okm);
          (okm ? hi : lo) = m;
        }
        *d = hi;
        const double mass = at(hi, w, &ok);
        return ok ? mass : kInf;
      };
      bool ok = false;
      double best_mass = at(x[r.d], x[r.t], &ok);
      if (!ok) best_mass = kInf;
      double best_d = x[r.d], best_w = x[r.t];
      auto wall = [&](int i) { return tt.lower() * std::pow(tt.upper() / tt.lower(), static_cast<double>(i) / kWalls); };
      int best_i = -1;
      for (int i = 0; i <= kWalls; ++i) {
        const double w = wall(i);
        bool unused = false;
        if (!(at(dd.lower(), w, &unused) < best_mass)) break;  // thicker walls only weigh more
        double d = 0.0;
        const double mass = least(w, &d);
        if (mass < best_mass) best_mass = mass, best_d = d, best_w = w, best_i = i;
      }
      // Between the grid's neighbours of the best wall: a golden-section search along the
      // requirement (each wall at its least diameter; +inf where none fits, so it closes in on a
      // wall where the diameter reaches its upper end).
      if (best_i >= 0) {
        double a = wall(std::max(0, best_i - 1)), b = wall(std::min(kWalls, best_i + 1));
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        double c = b - g * (b - a), e = a + g * (b - a), dc = 0.0, de = 0.0;
        double fc = least(c, &dc), fe = least(e, &de);
        for (int s = 0; s < kSteps; ++s) {
          if (fc < best_mass) best_mass = fc, best_d = dc, best_w = c;
          if (fe < best_mass) best_mass = fe, best_d = de, best_w = e;
          if (fc < fe) {
            b = e, e = c, fe = fc, de = dc;
            c = b - g * (b - a);
            fc = least(c, &dc);
          } else {
            a = c, c = e, fc = fe, dc = de;
            e = a + g * (b - a);
            fe = least(e, &de);
          }
        }
      }
      loads = keep;
      if (best_d != x[r.d] || best_w != x[r.t]) {
        next[r.d] = best_d;
        next[r.t] = best_w;
        moved = true;
      }
    }
    if (!moved) break;
    const Candidate c = Try(next, whole);
    if (icsp::IsEmpty(c.box[objective_])) break;
    x = next;
    loads = c.box;
  }
}

/// The worst excess (WorstExcess) over `box` of each of `constraints`, in their order; `missing`
/// for one that is not an expression or whose enclosure is empty.
void Optimizer::Excesses(const Box& box, const std::vector<int>& constraints, double missing,
                         std::vector<double>& out) {
  out.assign(constraints.size(), missing);
  evaluator_->Reset(&box);
  for (std::size_t a = 0; a < constraints.size(); ++a) {
    const icsp::Constraint& con = net().constraint(icsp::ConstraintId{constraints[a]});
    if (con.kind != icsp::Constraint::Kind::kExpression) continue;
    const Interval g = evaluator_->Eval(con.root);
    if (!icsp::IsEmpty(g)) out[a] = WorstExcess(g, con.relation);
  }
}

/// r's own laws evaluated in order over `box` (its D and t as set there), so `box` holds the tube's
/// quantities and the evaluator is left reset on it for r's checks; with `within`, each is met
/// with its enclosure there: false when one runs empty.
bool Optimizer::EvalTubeLaws(const Resizable& r, Box& box, const Box* within) {
  for (const auto& [z, rhs] : r.laws) {
    evaluator_->Reset(&box);
    box[z] = within ? icsp::Meet((*within)[z], evaluator_->Eval(rhs)) : evaluator_->Eval(rhs);
    if (within && icsp::IsEmpty(box[z])) return false;
  }
  evaluator_->Reset(&box);
  return true;
}

/// The tubes' own lower bound (Options::tube_bound_splits; docs/optimize.md, Method 2). HC4 and
/// shaving revise one constraint at a time, so a tube's term is bounded at the corner its
/// diameter's and wall's lower ends make, each contracted by the capacity requirement at the
/// other's upper end; where the lightest tube lies inside the rectangle (with the buckling
/// stress, where tau_cr reaches tau_allow: the capacity min(tau_allow, tau_cr) 2 Ip / D has a kink
/// along D/t = const) that corner is far below it. Here each tube's (D, t) rectangle of `box` is
/// paved best first (the piece of least mass split across its relatively wider side): a piece is
/// dropped when its own laws (mass, capacity, stiffness, ...) evaluated over it fall outside their
/// enclosures in `box`, or a check that reads the tube fails at every point of it (the other
/// variables, the loads among them, at their enclosures in `box`: every solution in `box` has
/// them there), so every solution's (D, t) lies in a kept piece. The least mass of the kept pieces
/// bounds the term from below, and their hulls contract D, t and the tube's own quantities. Stops when that least piece's
/// mass is known within a tenth of relative_gap or after tube_bound_splits splits. False when a
/// tube keeps no piece: `box` holds no solution.
bool Optimizer::TubeBounds(Box& box, const std::vector<Box>& others) {
  if (resizable_.empty() || options_.tube_bound_splits <= 0) return true;
  // The boxes a piece is checked in: `box`, and `others` (the same designs at the other points);
  // the laws of a piece are met with their enclosures in each.
  std::vector<const Box*> in = {&box};
  for (const Box& o : others) in.push_back(&o);
  std::vector<Box> works;
  for (const Box* b : in) works.push_back(*b);
  const double eps = 0.1 * options_.relative_gap;
  constexpr int kGrid = 8;  // the first paving: kGrid x kGrid pieces
  struct Piece {
    Interval D, t;
    double lo = 0.0, hi = 0.0;  // the term's enclosure over the piece
    std::vector<Interval> z;    // the tube's own quantities over it (in `box`), as r.laws
  };
  for (const Resizable& r : resizable_) {
    const int D = design_[r.d], t = design_[r.t];
    // The piece's own quantities; false when the piece holds no solution.
    auto evaluate = [&](Piece& p) {
      ++counters_.tube_bound_pieces;
      for (std::size_t b = 0; b < in.size(); ++b) {
        Box& work = works[b];
        work[D] = p.D;
        work[t] = p.t;
        if (!EvalTubeLaws(r, work, in[b])) return false;
        for (int k : r.checks) {
          const icsp::Constraint& con = net().constraint(icsp::ConstraintId{k});
          if (Impossible(evaluator_->Eval(con.root), con.relation)) return false;
        }
      }
      p.lo = works[0][r.term].lower();
      p.hi = works[0][r.term].upper();
      p.z.clear();
      for (const auto& law : r.laws) p.z.push_back(works[0][law.first]);
      return true;
    };
    const Interval D0 = box[D], t0 = box[t];
    auto later = [](const Piece& a, const Piece& b) { return a.lo > b.lo; };
    std::priority_queue<Piece, std::vector<Piece>, decltype(later)> queue(later);
    auto cut = [](const Interval& x, int i, int n) {
      const double w = (x.upper() - x.lower()) / n;
      return Interval(i == 0 ? x.lower() : x.lower() + i * w, i == n - 1 ? x.upper() : x.lower() + (i + 1) * w);
    };
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        Piece p;
        p.D = cut(D0, i, kGrid);
        p.t = cut(t0, j, kGrid);
        if (evaluate(p)) queue.push(std::move(p));
      }
    // Best first: the lightest piece split across its relatively wider side, until its mass is
    // known within eps.
    for (int split = 0; !queue.empty() && split < options_.tube_bound_splits; ++split) {
      const Piece p = queue.top();
      if (p.hi - p.lo <= eps * std::fabs(p.lo)) break;
      queue.pop();
      const double wd = (p.D.upper() - p.D.lower()) / std::max(D0.upper() - D0.lower(), 1e-300);
      const double wt = (p.t.upper() - p.t.lower()) / std::max(t0.upper() - t0.lower(), 1e-300);
      Piece a = p, b = p;
      if (wd >= wt) {
        a.D = cut(p.D, 0, 2);
        b.D = cut(p.D, 1, 2);
      } else {
        a.t = cut(p.t, 0, 2);
        b.t = cut(p.t, 1, 2);
      }
      if (evaluate(a)) queue.push(std::move(a));
      if (evaluate(b)) queue.push(std::move(b));
    }
    // Restore the tube's own quantities for the next tube (its checks read this tube's as the boxes').
    for (std::size_t b = 0; b < in.size(); ++b) {
      works[b][D] = (*in[b])[D];
      works[b][t] = (*in[b])[t];
      for (const auto& [z, rhs] : r.laws) works[b][z] = (*in[b])[z];
    }
    if (queue.empty()) return false;
    // Every solution's (D, t) is in a kept piece: the least mass, and the hulls of D, t and the
    // tube's own quantities (its stiffness and inertia, which the loads read).
    const double lo = queue.top().lo;
    Interval hd = queue.top().D, ht = queue.top().t;
    std::vector<Interval> hz = queue.top().z;
    for (; !queue.empty(); queue.pop()) {
      const Piece& p = queue.top();
      hd = boost::numeric::hull(hd, p.D);
      ht = boost::numeric::hull(ht, p.t);
      for (std::size_t k = 0; k < hz.size(); ++k) hz[k] = boost::numeric::hull(hz[k], p.z[k]);
    }
    box[D] = icsp::Meet(box[D], hd);
    box[t] = icsp::Meet(box[t], ht);
    for (std::size_t k = 0; k < hz.size(); ++k) {
      const int z = r.laws[k].first;
      box[z] = icsp::Meet(box[z], hz[k]);
      if (icsp::IsEmpty(box[z])) return false;
    }
    box[r.term] = icsp::Meet(box[r.term], Interval(lo, kInf));
    if (icsp::IsEmpty(box[r.term])) return false;
    for (Box& work : works) {  // the contracted D and t hold at either point
      work[D] = box[D];
      work[t] = box[t];
    }
    for (const auto& law : r.laws) works[0][law.first] = box[law.first];
  }
  return true;
}

/// The contractor with the tubes' own bounds (TubeBounds) on `box` (propagated already): with
/// the boxes of the other points beside it, again while a round raises the objective's lower bound
/// by a tenth of the tolerance (the contracted tubes' stiffnesses and inertias raise the loads' lower
/// ends, which drop more pieces). False when `box` holds no solution.
bool Optimizer::TubeContract(Box& box) {
  if (tubes_ || resizable_.empty() || options_.tube_bound_splits <= 0) return true;
  for (int round = 0; round < kTubeBoundRounds; ++round) {
    // The same designs at the other points (ChooseOtherPoints): a robust design is in each box.
    std::vector<Box> others;
    if (have_scenario_)
      for (const std::vector<double>& point : other_points_) {
        Box o = AtPoint(point);
        for (int v : design_) o[v] = box[v];
        o[bound_] = box[bound_];
        if (propagator_->Propagate(o).status == icsp::Status::kInfeasible) return false;
        others.push_back(std::move(o));
      }
    const double before = box[objective_].lower();
    if (!TubeBounds(box, others)) return false;
    if (propagator_->Propagate(box).status == icsp::Status::kInfeasible) return false;
    if (!(box[objective_].lower() - before > 0.1 * options_.relative_gap * std::fabs(box[objective_].lower())))
      break;
  }
  return true;
}

/// The objective at x (the middle of its enclosure over the remaining domains; definitions only),
/// NaN where the laws reject x.
double Optimizer::ObjectiveAt(const std::vector<double>& x) {
  Box box = initial_;
  for (std::size_t i = 0; i < design_.size(); ++i) box[design_[i]] = Interval(x[i]);
  box[bound_] = icsp::Whole();
  if (propagator_->Propagate(box, definitions_).status == icsp::Status::kInfeasible) return std::nan("");
  return Mid(box[objective_]);
}

/// The polish (Options::polish_evaluations): a pattern search from the incumbent. The branch
/// and bound's searches move towards the ends of domains (the corner the objective likes, one
/// variable to its end), at a resolution of 2^-line_search_steps of the segment; a design that a
/// constraint binds through two variables (a tube's torque capacity, roughly D^3 t, against its
/// mass, roughly D t) is lighter along the constraint, with the wall thinner and the diameter
/// larger, a direction none of them takes. The moves, at a step h of each domain: every variable
/// towards less objective (by the local gradient at the incumbent), and every ordered pair of
/// design variables of one component, the first lighter by h, the second heavier by half the
/// objective the first saves; a move that the robust check accepts (Try: robust check, size and
/// peak, as every candidate) and that lowers the objective is repeated with a doubled step; one
/// that fails is not tried again at that h. h goes from 1/16 to 1e-3 of the domains (a quarter
/// each time no move improves; 1e-4 gained 0.01 kg on the A380-class flaps for about twice the
/// checks). Every accepted design is robustly feasible as any incumbent, so the certificate is
/// unchanged; only the incumbent improves (and with it the pruning and the shaving, which cut
/// against the best design). Run after CoordinateSearch (after the 1st, 2nd, 4th, ...
/// improvement; its own improvements count), in the first box after it whose lower bound is
/// raised by shaving once a tenth of max_seconds has passed, and once more at the end; each call
/// within a fifth of max_seconds (and within max_seconds: on the A320-class slats, 14 ms a check,
/// an unlimited polish took the whole 10 s from the branch and bound), and until the incumbent is
/// within the tolerance of `lower` (the least lower bound of the open and closed boxes then: the
/// branch and bound stops there too).
void Optimizer::Polish(double lower) {
  if (!found_ || tubes_ || options_.polish_evaluations <= 0) return;
  const std::size_t n = design_.size();
  const int stop = counters_.candidates + options_.polish_evaluations;
  const Tolerance tol{options_.relative_gap, options_.absolute_gap};
  const double until = std::min(options_.max_seconds, Seconds() + 0.2 * options_.max_seconds);
  auto budget = [&] { return counters_.candidates < stop && Seconds() <= until && !tol.Closed(best_, lower); };
  std::vector<Interval> whole;
  std::vector<double> width(n);
  std::vector<std::string> owner(n);
  for (std::size_t i = 0; i < n; ++i) {
    whole.push_back(initial_[design_[i]]);
    width[i] = initial_[design_[i]].upper() - initial_[design_[i]].lower();
    owner[i] = design_names_[i].substr(0, design_names_[i].find('.'));
  }
  auto clamp = [&](std::size_t i, double v) {
    return std::clamp(v, initial_[design_[i]].lower(), initial_[design_[i]].upper());
  };
  // The objective's change per unit of each domain's width at the incumbent (a difference of 1e-4
  // of the domain, upwards, downwards at the upper end); again before each sweep of the moves.
  std::vector<double> grad(n);
  auto gradient = [&] {
    const std::vector<double> x = best_x_;
    const double at = ObjectiveAt(x);
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<double> b = x;
      b[i] = clamp(i, x[i] + 1e-4 * width[i]);
      if (b[i] == x[i]) b[i] = clamp(i, x[i] - 1e-4 * width[i]);
      const double d = (ObjectiveAt(b) - at) / ((b[i] - x[i]) / width[i]);
      grad[i] = std::isfinite(d) && b[i] != x[i] ? d : 0.0;
    }
  };
  // A move from the incumbent by `step` x the direction (in units of the domains' widths);
  // repeated with a doubled step while it improves. True when it improved once.
  auto move = [&](const std::vector<std::pair<std::size_t, double>>& dir, double step) {
    bool any = false;
    while (budget()) {
      std::vector<double> x = best_x_;
      bool moved = false;
      for (const auto& [i, d] : dir) {
        x[i] = clamp(i, best_x_[i] + step * d * width[i]);
        moved = moved || x[i] != best_x_[i];
      }
      if (!moved) break;
      const double before = best_;
      Try(x, whole);
      if (!(best_ < before)) break;
      any = true;
      step *= 2.0;
    }
    return any;
  };
  // The moves (i, i): variable i alone; (i, j): the pair. A move that fails at a step is not tried
  // again at that step (the others seldom free it; the next, smaller step tries it again).
  std::vector<std::pair<std::size_t, std::size_t>> moves;
  for (std::size_t i = 0; i < n; ++i) moves.push_back({i, i});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (i != j && owner[i] == owner[j]) moves.push_back({i, j});
  std::vector<char> failed(moves.size(), 0);
  for (double h = 1.0 / 16.0; h >= 1e-3 && budget();) {
    gradient();
    bool improved = false;
    for (std::size_t k = 0; k < moves.size() && budget(); ++k) {
      const auto [i, j] = moves[k];
      if (failed[k] || grad[i] == 0.0 || grad[j] == 0.0) continue;
      bool ok = false;
      if (i == j) {
        ok = move({{i, grad[i] > 0 ? -1.0 : 1.0}}, h);
      } else {  // i lighter by h (saves |grad_i| h), j heavier by what costs half of it
        const double dj = 0.5 * std::fabs(grad[i]) / std::fabs(grad[j]);
        ok = move({{i, grad[i] > 0 ? -1.0 : 1.0}, {j, grad[j] > 0 ? dj : -dj}}, h);
      }
      failed[k] = ok ? 0 : 1;
      improved = improved || ok;
    }
    if (!improved) {
      h *= 0.25;
      std::fill(failed.begin(), failed.end(), 0);
    }
  }
}

/// Feasible points inside a contracted box: the middle, else the corner the objective likes
/// least (the "safe" one); from the feasible one a bisection along the segment towards the
/// corner the objective likes most, keeping the farthest robustly feasible point.
void Optimizer::LocalSearch(const std::vector<Interval>& d) {
  const std::size_t n = d.size();
  std::vector<double> mid(n), light(n), safe(n);
  for (std::size_t i = 0; i < n; ++i) {
    mid[i] = Mid(d[i]);
    light[i] = sign_[i] > 0 ? d[i].lower() : sign_[i] < 0 ? d[i].upper() : mid[i];
    safe[i] = sign_[i] > 0 ? d[i].upper() : sign_[i] < 0 ? d[i].lower() : mid[i];
    // The objective does not read it: near the end the checks favour, a step of the line search
    // (2^-line_search_steps of the box) inside it, where a requirement that bounds it (the
    // extension time at the root box's end) holds for certain.
    if (prefer_[i] != 0.0)
      safe[i] = light[i] = light[i] - prefer_[i] * std::ldexp(d[i].upper() - d[i].lower(), -options_.line_search_steps);
  }
  std::vector<double> anchor = mid;
  Candidate c = Try(mid, d);
  if (!c.feasible) {
    if (safe == mid) return;
    c = Try(safe, d);
    if (!c.feasible) return;
    anchor = safe;
  }
  if (light == anchor) return;
  auto at = [&](double t) {
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = std::clamp(anchor[i] + t * (light[i] - anchor[i]), d[i].lower(), d[i].upper());
    return x;
  };
  {
    const Candidate e = Try(at(1.0), d);
    if (e.feasible) return;
  }
  double lo = 0.0, hi = 1.0;
  for (int s = 0; s < options_.line_search_steps; ++s) {
    const double t = 0.5 * (lo + hi);
    const Candidate e = Try(at(t), d);
    if (e.feasible) lo = t;
    else hi = t;
  }
}

/// One shaving trial: is "v <= its lower bound + slice" empty in `box` (propagated)? If the
/// propagation proves it, no solution of the box has v there: v's lower end is cut off (a set
/// operation on the box, sound as the propagation is).
bool Optimizer::ShaveSlice(Box& box, int v, double slice, const std::vector<char>& enabled, bool tubes) {
  const Interval cur = box[v];
  const double cut = cur.lower() + slice;
  if (!(slice > 0.0) || !(cut < cur.upper())) return false;
  Box trial = box;
  trial[v] = Interval(cur.lower(), cut);
  ++counters_.shaving_propagations;
  if (shaving_propagator_->Propagate(trial, enabled).status != icsp::Status::kInfeasible &&
      (!tubes || TubeContract(trial)))
    return false;
  ++counters_.shaving_cuts;
  box[v] = Interval(cut, cur.upper());
  return true;
}

/// Lower bounding by contraction (3B on the objective, as IbexOpt's): `box` propagated with
/// objective <= best. Each term of the objective (a shaft's mass), then the objective itself, gets
/// Options::shaving_tries trials of a slice at its lower end: for a term, half the way from its
/// lower end to its value at the best design (again after a cut, a quarter of the slice after a
/// slice that stays), propagated over the constraints near it; for the objective, a quarter of the
/// gap (doubled after a cut), over the whole network. HC4's bound is the objective at the box's
/// lower corner (the thinnest walls at the least diameters); a slice it proves empty is a part of
/// the box no design that beats the best can be in. Returns the raised lower bound, +inf when the
/// box emptied (no design of the box beats the best).
double Optimizer::Shave(Box& box, double lb) {
  const int tries = options_.shaving_tries;
  auto gap = [&] { return best_ - std::max(lb, box[objective_].lower()); };
  if (!(gap() > 0.0)) return lb;
  const double n = static_cast<double>(std::max<std::size_t>(1, terms_.size()));
  bool cut = false;
  for (std::size_t k = 0; k < terms_.size(); ++k) {
    const int v = terms_[k];
    // The term at the best design: what this box's designs must undercut; the slice is half the
    // way to it (a term whose lower end already reaches it is left alone).
    const double small = 1e-3 * gap() / n;
    auto reach = [&] {
      const double target = found_ ? best_candidate_.box[v].upper() : box[v].lower() + gap() / n;
      return std::min(target, box[v].upper()) - box[v].lower();
    };
    if (!(reach() > small)) continue;
    double slice = 0.5 * reach();
    for (int t = 0; t < tries && slice > small; ++t) {
      if (ShaveSlice(box, v, slice, term_constraints_[k])) {
        cut = true;
        slice = reach() > small ? 0.5 * reach() : gap() / n;
      } else {
        slice *= 0.25;
      }
    }
  }
  if (cut && propagator_->Propagate(box).status == icsp::Status::kInfeasible) return kInf;
  lb = std::max(lb, box[objective_].lower());
  double slice = 0.25 * gap();
  for (int t = 0; t < tries; ++t) {
    if (!(gap() > 0.0)) break;
    if (ShaveSlice(box, objective_, slice, {}, true)) {
      cut = true;
      slice *= 2.0;
      lb = std::max(lb, box[objective_].lower());
      if (propagator_->Propagate(box).status == icsp::Status::kInfeasible) return kInf;
      lb = std::max(lb, box[objective_].lower());
    } else {
      slice *= 0.25;
    }
  }
  return lb;
}

/// The constraints within two steps of each term (those on the term, and those on the variables
/// they involve: a shaft's mass law, then its capacity, stiffness, relations and the requirements
/// on its diameter and wall, with the peak loads at their current enclosures). A slice that this
/// subnetwork alone proves empty is empty for the whole network (fewer constraints admit more), and
/// its propagation costs a few revisions instead of a sweep of the whole network.
void Optimizer::ShavingNeighbourhoods() {
  const int depth = 2;
  term_constraints_.clear();
  for (int v : terms_) {
    std::vector<char> mask(net().num_constraints(), 0);
    std::vector<char> seen(net().num_variables(), 0);
    std::vector<int> frontier = {v};
    seen[v] = 1;
    for (int level = 0; level < depth; ++level) {
      std::vector<int> next;
      for (int x : frontier)
        for (int c : net().ConstraintsOf(icsp::VariableId{x})) {
          if (mask[c]) continue;
          mask[c] = 1;
          for (int y : net().ScopeOf(icsp::ConstraintId{c}))
            if (!seen[y]) seen[y] = 1, next.push_back(y);
        }
      frontier = std::move(next);
    }
    term_constraints_.push_back(std::move(mask));
  }
}

void Optimizer::Setup() {
  options_.Validate();
  ChooseDesignVariables();
  AddMargins();
  AddRelations();
  AddObjective();
  ClassifyConstraints();
  ProbeReducedModels();
  initial_ = net().InitialBox();
  for (const auto& [leader, common] : same_domains_) initial_[design_[leader]] = common;
  for (const Follower& f : followers_) initial_[f.var] = initial_[design_[f.leader]];
  for (const Component& c : project_.components)
    for (const auto& [pname, par] : c.parameters) {
      (void)par;
      const icsp::VariableId v = net().FindVariable(c.id + "." + pname);
      if (v.value < 0 || std::find(design_.begin(), design_.end(), v.value) != design_.end()) continue;
      if (std::any_of(followers_.begin(), followers_.end(), [&](const Follower& f) { return f.var == v.value; }))
        continue;
      const Interval d = initial_[v.value];
      if (std::isfinite(d.lower()) && std::isfinite(d.upper()) && d.upper() > d.lower()) uncertain_.push_back(v.value);
    }
  icsp::PropagationOptions po;
  po.ratio = options_.propagation_ratio;
  po.record_reasons = false;
  po.max_seconds = std::max(1.0, options_.max_seconds);
  propagator_ = std::make_unique<icsp::Propagator>(net(), po);
  icsp::PropagationOptions so = po;
  so.ratio = options_.shaving_ratio;
  shaving_propagator_ = std::make_unique<icsp::Propagator>(net(), so);
  ShavingNeighbourhoods();
  evaluator_ = std::make_unique<Evaluator>(net());
  SetupTubeSizes();
  FindSharedProducts();
  SetupResize();
}

std::string Optimizer::FailureText(const Candidate& c) const {
  if (!c.failed.empty()) {
    const int k = c.failed.front();
    if (k < 0) return "a law has no value for this design";
    const icsp::Constraint& con = dsn_.network.constraint(icsp::ConstraintId{k});
    return con.info.label + ": " + (con.info.source.empty() ? con.info.description : con.info.source);
  }
  return c.reduced_failure;
}

Report Optimizer::Run() {
  Setup();
  Report r;
  r.objective = options_.objective;
  r.design_variables = design_names_;
  r.objective_unit = objective_unit_;

  // The root: infeasible for every design? unbounded?
  Box root = initial_;
  const icsp::PropagationReport rep = propagator_->Propagate(root);
  if (rep.status == icsp::Status::kInfeasible) {
    icsp::PropagationOptions eo;
    eo.max_seconds = 30.0;
    const icsp::Explanation ex = icsp::Explain(net(), initial_, eo);
    r.status = Status::kInfeasible;
    r.infeasibility = ex.infeasible ? ex.text : rep.message;
    r.message = "no design within the domains of " + std::to_string(design_.size()) +
                " design variable(s) meets every requirement and margin (proved by propagation)";
    r.seconds = Seconds();
    return r;
  }
  if (tubes_ && !ContractTubes(root)) {
    r.status = Status::kInfeasible;
    r.message = "no design made of the sizes of --tube-sizes " + tubes_->table_name() +
                " meets every requirement and margin (proved by propagation with the table constraint)";
    r.infeasibility = "the sizes of the table within each shaft's domains are all outside what the constraint "
                      "network allows at the root; widen the shafts' domains or give a table with other sizes";
    r.seconds = Seconds();
    return r;
  }
  if (!std::isfinite(root[objective_].lower()))
    throw InputError("objective '" + options_.objective + "' is unbounded below over the domains ("
                     "no finite lower bound after propagation): give the "
                     "parameters it depends on finite \"min\" and \"max\" in the project, or minimize another objective");
  Sensitivities(root);
  {
    // A constraint that no design variable reaches (not even through the laws that define derived
    // quantities) and that does not hold for certain over the remaining domains fails for every
    // design alike: say so at once instead of searching.
    // Parameters are inputs: only design variables and the quantities derived from them are reached.
    std::vector<char> reached(net().num_variables(), 0), parameter(net().num_variables(), 0);
    for (const Component& c : project_.components)
      for (const auto& entry : c.parameters) {
        const icsp::VariableId v = net().FindVariable(c.id + "." + entry.first);
        if (v.value >= 0) parameter[v.value] = 1;
      }
    for (int v : design_) reached[v] = 1;
    for (bool changed = true; changed;) {
      changed = false;
      for (int c = 0; c < net().num_constraints(); ++c) {
        if (!definitions_[c]) continue;
        const auto scope = net().ScopeOf(icsp::ConstraintId{c});
        if (std::none_of(scope.begin(), scope.end(), [&](int v) { return reached[v] != 0; })) continue;
        for (int v : scope)
          if (!reached[v] && !parameter[v]) reached[v] = changed = true;
      }
    }
    std::vector<double> mid;
    for (int v : design_) mid.push_back(Mid(initial_[v]));
    const Candidate probe = Evaluate(mid, false);
    std::vector<std::string> fixed;
    for (int k : probe.failed) {
      if (k < 0) continue;
      const auto scope = net().ScopeOf(icsp::ConstraintId{k});
      if (std::any_of(scope.begin(), scope.end(), [&](int v) { return reached[v] != 0; })) continue;
      const icsp::Constraint& con = net().constraint(icsp::ConstraintId{k});
      std::string vars;
      for (int v : scope) vars += (vars.empty() ? "" : ", ") + net().variable(icsp::VariableId{v}).name;
      fixed.push_back(con.info.label + ": " + (con.info.source.empty() ? con.info.description : con.info.source) +
                      " (over " + vars + ")");
    }
    if (!fixed.empty()) {
      r.status = Status::kNoDesignFound;
      r.message = "no design variable reaches " + std::to_string(fixed.size()) +
                  " constraint(s) that do not hold for every value of their uncertain parameters, so no design can "
                  "be robustly feasible: make one of their parameters a design variable (\"design\": true or "
                  "--design) or narrow its domain";
      r.infeasibility = "Constraints that fail for every design:\n";
      for (const std::string& f : fixed) r.infeasibility += "  - " + f + "\n";
      r.lower_bound = icsp::ToDisplay(root[objective_].lower(), objective_unit_);
      r.candidates = counters_.candidates;
      r.seconds = Seconds();
      return r;
    }
  }

  {
    // `peak` over the whole design domains: a margin that fails at every point proves that no
    // design passes `highlift peak` (its enclosures are guaranteed), before any search.
    std::vector<Interval> d;
    for (int v : design_) d.push_back(root[v]);
    const std::string proof = PeakProof(d);
    if (!proof.empty()) {
      r.status = Status::kInfeasible;
      r.message = "no design within the domains of " + std::to_string(design_.size()) +
                  " design variable(s) passes `highlift peak` (proved by peak's enclosures over the whole domains)";
      r.infeasibility = "  - " + proof +
                        "\nfor every value of the design variables; give the component a larger allowable "
                        "(a design variable or a wider domain) or widen the domains that lower its load\n";
      r.peak_checks = counters_.peak_checks;
      r.peak_pruned = 1;
      r.lower_bound = icsp::ToDisplay(root[objective_].lower(), objective_unit_);
      r.seconds = Seconds();
      return r;
    }
  }

  struct Node {
    std::vector<Interval> d;
    double lb;
    /// Lower ends of the objective's terms proved by shaving (empty: none), valid for the
    /// relaxation they were proved in: -1 with the uncertain parameters free (valid at any point),
    /// else the generation of the worst-case point.
    std::vector<double> term_lo;
    int term_generation = -1;
  };
  auto worse = [](const Node& a, const Node& b) { return a.lb > b.lb; };
  std::priority_queue<Node, std::vector<Node>, decltype(worse)> queue(worse);
  {
    Node n;
    for (int v : design_) n.d.push_back(root[v]);
    n.lb = root[objective_].lower();
    queue.push(std::move(n));
  }
  const Tolerance tol{options_.relative_gap, options_.absolute_gap};
  double closed_lb = kInf;   // least lower bound of the boxes closed within the tolerance
  bool unproved = false;     // a box was closed without a proof (tiny, no design found in it)
  bool limit = false;
  int next_polish = 1;  // improvements count at which CoordinateSearch and ChooseScenario run next
  bool polish_due = false;  // Polish after this box's lower bound is known (its shaving)
  while (!queue.empty()) {
    // With a cut-off (another part combination's best), closing on it means nothing here is better.
    if ((found_ || cut_off_) && tol.Closed(best_, std::min(closed_lb, queue.top().lb))) break;
    if (counters_.boxes >= options_.max_boxes || Seconds() > options_.max_seconds) {
      limit = true;
      break;
    }
    Node node = queue.top();
    queue.pop();
    ++counters_.boxes;
    if (node.lb > best_) {
      ++counters_.pruned;
      continue;
    }
    Box box = have_scenario_ ? AtPoint(scenario_) : initial_;
    const int generation = have_scenario_ ? scenario_generation_ : -1;
    for (std::size_t i = 0; i < design_.size(); ++i) box[design_[i]] = node.d[i];
    box[bound_] = std::isfinite(best_) ? Interval(-kInf, best_) : icsp::Whole();
    if (!node.term_lo.empty() && (node.term_generation < 0 || node.term_generation == generation))
      for (std::size_t t = 0; t < terms_.size(); ++t)
        box[terms_[t]] = icsp::Meet(box[terms_[t]], Interval(node.term_lo[t], kInf));
    icsp::PropagationReport pr = propagator_->Propagate(box);
    if (pr.status != icsp::Status::kInfeasible && !TubeContract(box)) pr.status = icsp::Status::kInfeasible;
    if (pr.status == icsp::Status::kInfeasible || (tubes_ && !ContractTubes(box))) {
      if (std::isfinite(best_)) ++counters_.pruned;
      else ++counters_.infeasible_boxes;
      continue;
    }
    double lb = std::max(node.lb, box[objective_].lower());
    if (counters_.boxes == 1) root_lb_ = lb;
    if ((found_ || cut_off_) && tol.Closed(best_, lb)) {
      closed_lb = std::min(closed_lb, lb);
      continue;
    }
    std::vector<Interval> d(design_.size());
    for (std::size_t i = 0; i < design_.size(); ++i) d[i] = box[design_[i]];
    if (const std::string proof = PeakProof(d); !proof.empty()) {
      ++counters_.peak_pruned;
      ++peak_proofs_[proof.substr(0, proof.find(" carries"))];
      continue;
    }
    LocalSearch(d);
    // After the 1st, 2nd, 4th, ... improvement: the count may pass a power of two within one local
    // search (several improvements in one box), so the next polish is due when it reaches it.
    if (counters_.improvements >= next_polish) {
      ResizeTubes();
      CoordinateSearch();
      ChooseScenario();
      polish_due = true;
      while (next_polish <= counters_.improvements) next_polish *= 2;
    }
    if ((found_ || cut_off_) && tol.Closed(best_, lb)) {
      closed_lb = std::min(closed_lb, lb);
      continue;
    }
    std::vector<double> term_lo;
    if (options_.shaving_tries > 0 && std::isfinite(best_)) {
      box[bound_] = Interval(-kInf, best_);
      const double shaved = Shave(box, lb);
      if (!std::isfinite(shaved)) {  // no design of the box beats the best
        ++counters_.pruned;
        continue;
      }
      if (tubes_ && !ContractTubes(box)) {  // the shaved box holds no size
        ++counters_.pruned;
        continue;
      }
      lb = std::max(lb, shaved);
      if (tubes_) lb = std::max(lb, box[objective_].lower());
      if (counters_.boxes == 1) root_lb_ = lb;
      if (tol.Closed(best_, lb)) {
        closed_lb = std::min(closed_lb, lb);
        continue;
      }
      for (std::size_t i = 0; i < design_.size(); ++i) d[i] = box[design_[i]];
      for (int v : terms_) term_lo.push_back(box[v].lower());
    }
    // Against the bound as tight as it is now (it stops once the gap closes); not within the first
    // tenth of max_seconds, where a search that closes needs none (the A320-class flaps in 0.7 s).
    if (polish_due && Seconds() >= 0.1 * options_.max_seconds) {
      polish_due = false;
      Polish(std::min({closed_lb, lb, queue.empty() ? kInf : queue.top().lb}));
      if (tol.Closed(best_, lb)) {
        closed_lb = std::min(closed_lb, lb);
        continue;
      }
    }
    const int k = ChooseSplit(d);
    if (k < 0) {  // too small to split further
      closed_lb = std::min(closed_lb, lb);
      if (!found_) unproved = true;
      continue;
    }
    const double m = Mid(d[k]);
    Node a{d, lb, term_lo, generation}, b{d, lb, term_lo, generation};
    a.d[k] = Interval(d[k].lower(), m);
    b.d[k] = Interval(m, d[k].upper());
    queue.push(std::move(a));
    queue.push(std::move(b));
  }
  double lower = closed_lb;
  if (!queue.empty()) lower = std::min(lower, queue.top().lb);
  Polish(lower);
  if (found_) lower = std::min(lower, best_);
  r.boxes = counters_.boxes;
  r.pruned = counters_.pruned;
  r.infeasible_boxes = counters_.infeasible_boxes;
  r.candidates = counters_.candidates;
  r.reduced_model_checks = counters_.reduced_model_checks;
  r.improvements = counters_.improvements;
  r.peak_checks = counters_.peak_checks;
  r.peak_pruned = counters_.peak_pruned;
  r.shaving_propagations = counters_.shaving_propagations;
  r.shaving_cuts = counters_.shaving_cuts;
  r.tube_bound_pieces = counters_.tube_bound_pieces;
  r.root_lower_bound = icsp::ToDisplay(root_lb_, objective_unit_);
  {
    std::vector<std::pair<std::string, int>> why(rejected_.begin(), rejected_.end());
    std::stable_sort(why.begin(), why.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    if (why.size() > 5) why.resize(5);
    r.rejections = why;
  }
  if (!found_ && cut_off_ && !unproved && !limit) {
    r.status = Status::kNoDesignFound;
    r.message = "cut off: no design better than " + FormatNumber(icsp::ToDisplay(best_, objective_unit_), 6) + " " +
                objective_unit_ + " (the best of the other part choices)";
    r.lower_bound = icsp::ToDisplay(std::min(lower, best_), objective_unit_);
    r.seconds = Seconds();
    return r;
  }
  if (!found_) {
    if (queue.empty() && !unproved && !limit) {
      r.status = Status::kInfeasible;
      r.message = "no design within the domains meets every requirement and margin: branch and bound emptied every box";
      if (tubes_) r.message += " (each shaft one of the sizes of --tube-sizes " + tubes_->table_name() + ")";
      const icsp::Explanation ex = icsp::Explain(net(), initial_, {});
      if (ex.infeasible) {
        r.infeasibility = ex.text;
      } else {
        r.infeasibility = "the domains together admit values, but no box of design variables does (" +
                          std::to_string(counters_.infeasible_boxes) + " emptied by the constraint network, " +
                          std::to_string(counters_.peak_pruned) + " proved by `peak` to hold no design that passes it";
        r.infeasibility += peak_proofs_.empty() ? ")" : ":";
        r.infeasibility += "\n";
        for (const auto& [what, n] : peak_proofs_)
          r.infeasibility += "  - " + std::to_string(n) + " x " + what + " exceeds its allowable everywhere\n";
        r.infeasibility += "widen the design domains or relax the requirements";
      }
    } else {
      r.status = Status::kNoDesignFound;
      r.message = "gave up without a robustly feasible design (" + std::string(limit ? "limit reached" : "boxes too small") +
                  "); this proves nothing: raise max_boxes / max_seconds or widen the design domains";
      if (!verification_note_.empty()) r.message += "; " + verification_note_;
    }
    r.lower_bound = icsp::ToDisplay(lower, objective_unit_);
    r.seconds = Seconds();
    return r;
  }
  r.found = true;
  r.status = tol.Closed(best_, lower) ? Status::kOptimal : Status::kStoppedAtLimit;
  r.best = icsp::ToDisplay(best_, objective_unit_);
  r.lower_bound = icsp::ToDisplay(lower, objective_unit_);
  r.gap = best_ != 0.0 ? (best_ - lower) / std::fabs(best_) : best_ - lower;
  r.message = r.status == Status::kOptimal ? "the gap closed within the tolerance"
                                           : "limit reached (" + std::to_string(counters_.boxes) + " boxes, " +
                                                 FormatNumber(Seconds(), 3) + " s) with the gap open";
  if (!verification_note_.empty()) r.message += "; " + verification_note_;
  if (!scenario_note_.empty()) r.message += "; " + scenario_note_;
  Finish(r);
  r.seconds = Seconds();
  return r;
}

/// The design table, the mass terms, the active constraints and the project of the design.
void Optimizer::Finish(Report& r) {
  std::vector<std::pair<std::string, double>> values;
  for (std::size_t i = 0; i < design_.size(); ++i) {
    const icsp::VariableInfo& info = net().variable(icsp::VariableId{design_[i]});
    DesignValue dv;
    dv.name = design_names_[i];
    dv.unit = info.unit;
    dv.value = icsp::ToDisplay(best_x_[i], info.unit);
    dv.value_si = best_x_[i];
    dv.lower = icsp::ToDisplay(initial_[design_[i]].lower(), info.unit);
    dv.upper = icsp::ToDisplay(initial_[design_[i]].upper(), info.unit);
    dv.nominal = std::nan("");
    for (const auto& [var, nominal] : dsn_.nominal)
      if (var == design_[i]) dv.nominal = icsp::ToDisplay(nominal, info.unit);
    const double w = initial_[design_[i]].upper() - initial_[design_[i]].lower();
    if (best_x_[i] - initial_[design_[i]].lower() <= 1e-6 * w) dv.at_bound = "lower";
    if (initial_[design_[i]].upper() - best_x_[i] <= 1e-6 * w) dv.at_bound = "upper";
    r.design.push_back(dv);
  }
  for (const Follower& f : followers_) {
    DesignValue dv = r.design[f.leader];
    dv.name = f.name;
    dv.same_as = design_names_[f.leader];
    dv.nominal = std::nan("");
    for (const auto& [var, nominal] : dsn_.nominal)
      if (var == f.var) dv.nominal = icsp::ToDisplay(nominal, dv.unit);
    r.design.push_back(dv);
  }
  values = DesignValues(best_x_);
  for (std::size_t t = 0; t < mass_terms_.size(); ++t) {
    MassTerm m = mass_terms_[t];
    if (mass_vars_[t] >= 0) {
      m.lower = best_candidate_.box[mass_vars_[t]].lower();
      m.upper = best_candidate_.box[mass_vars_[t]].upper();
    }
    r.mass_terms.push_back(m);
  }
  // Active constraints: what breaks one small step (1e-4 of each domain) towards a smaller
  // objective, and the design variables at a bound of their domains.
  const Candidate c = Evaluate(StepTowardsSmaller(best_x_), true);
  std::set<int> seen;
  for (int k : c.failed) {
    if (k < 0 || !seen.insert(k).second) continue;
    const icsp::Constraint& con = net().constraint(icsp::ConstraintId{k});
    // Skip what already failed at the optimum (cannot happen for a feasible design, kept safe).
    r.active.push_back({con.info.label, con.info.description,
                        con.info.source.empty() ? net().ConstraintText(icsp::ConstraintId{k}) : con.info.source});
  }
  if (c.failed.empty() && !c.reduced_failure.empty())
    r.active.push_back({c.reduced_failure.substr(0, c.reduced_failure.find(':')), c.reduced_failure, ""});
  for (const DesignValue& dv : r.design)
    if (!dv.at_bound.empty())
      r.active.push_back({"bound:" + dv.name, dv.name + " at the " + dv.at_bound + " end of its domain",
                          dv.name + (dv.at_bound == "lower" ? " >= " : " <= ") +
                              FormatNumber(dv.at_bound == "lower" ? dv.lower : dv.upper, 6) + " " + dv.unit});
  r.design_project = FixDesign(project_, values);
  FinishTubeSizes(r);
}

/// Options::tube_sizes: the table constraint (tube_sizes.h) over the design variables.
void Optimizer::SetupTubeSizes() {
  if (options_.tube_sizes.sizes.empty()) return;
  std::vector<Interval> domains;
  for (int v : design_) domains.push_back(initial_[v]);
  tubes_ = std::make_unique<TubeConstraint>(options_.tube_sizes, project_, design_names_, domains,
                                            [&](const std::string& name) {
                                              const icsp::VariableId v = net().FindVariable(name);
                                              return v.value < 0 ? icsp::Whole() : initial_[v.value];
                                            });
}

/// The box's design variables contracted by the table constraint, then the box propagated again
/// while the table narrows it (at most 4 rounds; the box ends on the hull of its sizes). False when
/// a shaft has no size left in the box or the propagation empties it: no design of the box is made
/// of the table's sizes and meets the constraints.
bool Optimizer::ContractTubes(Box& box) {
  std::vector<Interval> d(design_.size());
  for (int round = 0;; ++round) {
    for (std::size_t i = 0; i < design_.size(); ++i) d[i] = box[design_[i]];
    bool changed = false;
    if (!tubes_->Contract(d, changed)) return false;
    if (!changed) return true;
    for (std::size_t i = 0; i < design_.size(); ++i) box[design_[i]] = d[i];
    if (round == 3) return true;
    if (propagator_->Propagate(box).status == icsp::Status::kInfeasible) return false;
  }
}

/// A candidate design checked and considered as the incumbent; with tube sizes, the designs made
/// of sizes near it inside the box `d` instead (TubeConstraint::Snap): every shaft at its nearest
/// size; when that is robustly feasible, also every shaft at its nearest size at most as large
/// (lighter, maybe still feasible), else at its nearest size at least as large (stronger). The
/// robustly feasible lighter of the two is returned, else the nearest's outcome.
Candidate Optimizer::Try(const std::vector<double>& x, const std::vector<Interval>& d) {
  if (!tubes_) {
    Candidate c = Evaluate(x, true);
    Consider(x, c);
    return c;
  }
  const TubeConstraint::Snapped s = tubes_->Snap(x, d);
  Candidate c = Evaluate(s.nearest, true);
  Consider(s.nearest, c);
  const std::vector<double>& next = c.feasible ? s.down : s.up;
  if (next == s.nearest) return c;
  Candidate e = Evaluate(next, true);
  Consider(next, e);
  return e.feasible && (!c.feasible || e.value < c.value) ? e : c;
}

/// The report names each restricted shaft's size; the project of the design says it in the notes.
/// What limits a size: the best design with one shaft at its next lighter size (the heaviest of
/// the sizes within its domains with a smaller (D - t) t, the tube law's factor) is checked, and
/// what fails there is listed with the shaft and the size.
void Optimizer::FinishTubeSizes(Report& r) {
  if (!tubes_) return;
  r.tube_table = tubes_->table_name();
  r.tube_sizes = tubes_->Sizes(best_x_);
  for (std::size_t k = 0; k < r.tube_sizes.size(); ++k) {
    const TubeShaft& s = tubes_->shafts()[k];
    const double D = s.diameter >= 0 ? best_x_[s.diameter] : 0.0, t = s.wall >= 0 ? best_x_[s.wall] : 0.0;
    auto factor = [&](std::size_t j) {
      return ((s.diameter >= 0 ? s.D[j] : D) - (s.wall >= 0 ? s.t[j] : t)) * (s.wall >= 0 ? s.t[j] : t);
    };
    const double current = (D - t) * t;
    int lighter = -1;
    for (std::size_t j = 0; j < s.D.size(); ++j)
      if (factor(j) < current && (lighter < 0 || factor(j) > factor(lighter))) lighter = static_cast<int>(j);
    if (lighter >= 0 && s.diameter >= 0 && s.wall >= 0) {
      std::vector<double> x = best_x_;
      x[s.diameter] = s.D[lighter];
      x[s.wall] = s.t[lighter];
      const Candidate c = Evaluate(x, true);
      const std::string at = " (" + s.component + " at its next lighter size " + s.designations[lighter] + ")";
      for (int f : c.failed) {
        if (f < 0) continue;
        const icsp::Constraint& con = net().constraint(icsp::ConstraintId{f});
        r.active.push_back({con.info.label, con.info.description + at,
                            con.info.source.empty() ? net().ConstraintText(icsp::ConstraintId{f}) : con.info.source});
      }
      if (c.failed.empty() && !c.reduced_failure.empty())
        r.active.push_back({c.reduced_failure.substr(0, c.reduced_failure.find(':')), c.reduced_failure + at, ""});
    }
    for (int i : {s.diameter, s.wall}) {
      if (i < 0) continue;
      r.design[i].tube_size = r.tube_sizes[k].second;
      if (r.design_project) {
        const std::string& name = design_names_[i];
        r.design_project->FindComponent(s.component)->parameters[name.substr(name.find('.') + 1)].note =
            "highlift optimize: tube size " + r.tube_sizes[k].second + " of --tube-sizes " + r.tube_table;
      }
    }
  }
}

}  // namespace detail

namespace {
std::string Number(double v) { return FormatNumber(v, 6); }
/// The number, or null when it is not finite (NaN: none; infinite: unbounded).
nlohmann::json FiniteOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
}  // namespace

DesignEvaluator::DesignEvaluator(const Project& project, const Options& options)
    : impl_(std::make_unique<detail::Optimizer>(project, options)) {
  impl_->Setup();
}
DesignEvaluator::~DesignEvaluator() = default;
const std::vector<std::string>& DesignEvaluator::variables() const { return impl_->design_names(); }
std::vector<std::pair<double, double>> DesignEvaluator::domains() const { return impl_->domains(); }
PointCheck DesignEvaluator::Check(const std::vector<double>& x) {
  if (x.size() != impl_->design_names().size())
    throw InputError("DesignEvaluator::Check: " + std::to_string(x.size()) + " values for " +
                     std::to_string(impl_->design_names().size()) + " design variables; give one per variable");
  const Candidate c = impl_->Evaluate(x, true);
  PointCheck out;
  out.feasible = c.feasible;
  out.objective = c.feasible ? icsp::ToDisplay(c.value, impl_->objective_unit()) : kInf;
  if (!c.feasible) out.failure = impl_->FailureText(c);
  return out;
}

void Options::Validate() const {
  if (objective.empty()) throw InputError("optimize: the objective is empty; give 'mass', 'inertia' or an expression");
  if (max_boxes < 1) throw InputError("optimize: max_boxes = " + std::to_string(max_boxes) + " must be >= 1");
  if (!(relative_gap >= 0.0) || !std::isfinite(relative_gap))
    throw InputError("optimize: relative_gap = " + Number(relative_gap) + " must be a finite number >= 0");
  if (!(absolute_gap >= 0.0) || !std::isfinite(absolute_gap))
    throw InputError("optimize: absolute_gap = " + Number(absolute_gap) + " must be a finite number >= 0");
  if (!(max_seconds > 0.0) || !std::isfinite(max_seconds))
    throw InputError("optimize: max_seconds = " + Number(max_seconds) + " must be a finite number > 0");
  if (line_search_steps < 0 || line_search_steps > 60)
    throw InputError("optimize: line_search_steps = " + std::to_string(line_search_steps) + " must be from 0 to 60");
  if (polish_evaluations < 0)
    throw InputError("optimize: polish_evaluations = " + std::to_string(polish_evaluations) +
                     " must be >= 0 (0: no polish)");
  if (tube_bound_splits < 0)
    throw InputError("optimize: tube_bound_splits = " + std::to_string(tube_bound_splits) +
                     " must be >= 0 (0: no tube lower bound)");
  if (resize_iterations < 0)
    throw InputError("optimize: resize_iterations = " + std::to_string(resize_iterations) +
                     " must be >= 0 (0: the incumbent's tubes are not resized)");
  if (!pareto.empty() && (pareto == "mass" || pareto == "inertia"))
    throw InputError("optimize: the second objective of --pareto is bounded by a constraint, so it must be an "
                     "expression of the constraint language, not '" + pareto + "'; give '" + pareto +
                     "' first (--pareto " + pareto + ",EXPR)");
  if (!pareto.empty() && (pareto_points < 2 || pareto_points > 50))
    throw InputError("optimize: pareto_points = " + std::to_string(pareto_points) + " must be from 2 to 50");
  if (!pareto.empty() && !choose_part.empty())
    throw InputError("optimize: --pareto and --choose-part together are not supported; give one of them");
  if (!tube_sizes.sizes.empty() && !choose_part.empty())
    throw InputError("optimize: --tube-sizes and --choose-part together are not supported; a database tube part "
                     "already fixes its diameter and wall: give one of them");
  if (max_part_combinations < 1)
    throw InputError("optimize: max_part_combinations = " + std::to_string(max_part_combinations) + " must be >= 1");
  for (const PartChoice& c : choose_part)
    if (c.parts.empty())
      throw InputError("optimize: no part to choose from for component '" + c.component +
                       "'; give at least one part (the database's parts of its type)");
  std::set<std::string> grouped;
  for (const std::vector<std::string>& group : same_value) {
    if (group.size() < 2)
      throw InputError("optimize: a same_value group names " + std::to_string(group.size()) +
                       " parameter(s); give at least two (the design variable first, then the parameters that follow it)");
    for (const std::string& name : group)
      if (!grouped.insert(name).second)
        throw InputError("optimize: '" + name + "' is named twice in same_value; give each parameter in one group once");
  }
  if (dependency_splits < 0 || dependency_splits > 10000)
    throw InputError("optimize: dependency_splits = " + std::to_string(dependency_splits) + " must be from 0 to 10000");
  if (shaving_tries < 0 || shaving_tries > 20)
    throw InputError("optimize: shaving_tries = " + std::to_string(shaving_tries) + " must be from 0 to 20");
  if (!(shaving_ratio >= 0.0 && shaving_ratio < 1.0))
    throw InputError("optimize: shaving_ratio = " + Number(shaving_ratio) + " must be in [0, 1)");
  if (!(propagation_ratio >= 0.0 && propagation_ratio < 1.0))
    throw InputError("optimize: propagation_ratio = " + Number(propagation_ratio) + " must be in [0, 1)");
}

std::string ToString(Status s) {
  switch (s) {
    case Status::kOptimal: return "optimal";
    case Status::kStoppedAtLimit: return "stopped_at_limit";
    case Status::kInfeasible: return "infeasible";
    case Status::kNoDesignFound: return "no_design_found";
  }
  return "unknown";
}

std::optional<Status> StatusFromString(const std::string& s) {
  for (Status v : {Status::kOptimal, Status::kStoppedAtLimit, Status::kInfeasible, Status::kNoDesignFound})
    if (ToString(v) == s) return v;
  return std::nullopt;
}

Project FixDesign(const Project& project, const std::vector<std::pair<std::string, double>>& values) {
  Project p = project;
  for (const auto& [name, value] : values) {
    const auto dot = name.find('.');
    Component* c = dot == std::string::npos ? nullptr : p.FindComponent(name.substr(0, dot));
    if (!c) throw InputError("design variable '" + name + "': no such component in the project");
    Parameter& par = c->parameters[name.substr(dot + 1)];
    par.nominal = value;
    par.domain = Domain::Point(value);
    par.provenance = Provenance::kOptimized;
    par.note = "highlift optimize";
    par.design = false;
  }
  return p;
}

std::string Report::BriefReport() const {
  std::ostringstream o;
  o << ToString(status) << ": ";
  if (found) {
    o << objective << " " << Number(best) << (objective_unit.empty() ? "" : " " + objective_unit) << ", certified >= "
      << Number(lower_bound) << " (gap " << FormatNumber(gap, 3) << ")";
  } else {
    o << message;
  }
  o << ", " << boxes << " boxes, " << candidates << " candidate designs in " << FormatNumber(seconds, 3) << " s";
  return o.str();
}

std::string Report::FullReport() const {
  std::ostringstream o;
  if (!found) {
    o << message << "\n";
    if (!infeasibility.empty()) o << "\nWhy:\n" << infeasibility << (infeasibility.back() == '\n' ? "" : "\n");
    if (!rejections.empty()) {
      o << "\nCandidate designs were rejected by (first failing check, count):\n";
      for (const auto& [what, n] : rejections) o << "  " << n << " x " << what << "\n";
    }
  } else {
    o << "Best design (" << message << "):\n";
    std::vector<std::string> columns = {"design variable", "unit", "optimized", "domain", "nominal", "at bound"};
    if (!tube_table.empty()) columns.push_back("tube size");
    TextTable t(columns, {2, 4});
    for (const DesignValue& d : design) {
      std::vector<std::string> row = {d.same_as.empty() ? d.name : d.name + " (= " + d.same_as + ")", d.unit, Number(d.value), "[" + Number(d.lower) + ", " + Number(d.upper) + "]",
                                      std::isfinite(d.nominal) ? Number(d.nominal) : "-", d.at_bound};
      if (!tube_table.empty()) row.push_back(d.tube_size);
      t.AddRow(row);
    }
    o << t.ToString();
    for (const auto& [component, designation] : parts) o << "part of " << component << ": " << designation << "\n";
    for (const auto& [component, size] : tube_sizes)
      o << "tube of " << component << ": " << size << " (--tube-sizes " << tube_table << ")\n";
    o << "\nObjective " << objective << ": " << Number(best) << " " << objective_unit
      << " (upper bound over the remaining uncertain parameters); certified lower bound " << Number(lower_bound) << " "
      << objective_unit << "; relative gap " << FormatNumber(gap, 3) << "\n";
    if (!mass_terms.empty()) {
      o << "\nMass by component (kg over the remaining domains, at the best design):\n";
      TextTable m({"component", "min", "max", "law"}, {1, 2});
      for (const MassTerm& mt : mass_terms)
        m.AddRow({mt.component, std::isfinite(mt.lower) ? Number(mt.lower) : "-",
                  std::isfinite(mt.upper) ? Number(mt.upper) : "-", mt.law});
      o << m.ToString();
    }
    o << "\nWhat limits the design (breaks one step of 1e-4 of the domains towards a smaller " << objective
      << (tube_table.empty() ? "" : ", or a shaft's next lighter tube size") << "):\n";
    if (active.empty()) o << "  nothing found at that step\n";
    for (const ActiveConstraint& a : active)
      o << "  - " << a.label << ": " << a.description << (a.text.empty() ? "" : "\n      " + a.text) << "\n";
  }
  if (!pareto.empty()) {
    o << "\nPareto front (" << objective << " against " << pareto_objective << "):\n";
    TextTable t({pareto_objective + " <= [" + pareto_unit + "]", objective + " [" + objective_unit + "]",
                 "certified >=", pareto_objective + " at the design", "status"},
                {0, 1, 2, 3});
    for (const ParetoPoint& p : pareto)
      t.AddRow({Number(p.epsilon), Number(p.objective), Number(p.lower_bound),
                std::isfinite(p.second) ? Number(p.second) : "-", p.status});
    o << t.ToString();
  }
  if (!combinations.empty()) {
    o << "\nPart combinations searched:\n";
    TextTable c({"parts", "status", "best", "lower bound"}, {2, 3});
    for (const Combination& k : combinations) {
      std::string names;
      for (const std::string& d : k.designations) names += (names.empty() ? "" : ", ") + d;
      c.AddRow({names, k.status, std::isfinite(k.best) ? Number(k.best) : "-",
                std::isfinite(k.lower_bound) ? Number(k.lower_bound) : "-"});
    }
    o << c.ToString();
  }
  o << "\n" << boxes << " boxes (" << pruned << " pruned by the bound, " << infeasible_boxes << " infeasible), "
    << candidates << " candidate designs checked (" << reduced_model_checks << " through size and peak), "
    << improvements << " improvements, ";
  if (peak_checks > 0)
    o << peak_checks << " boxes through peak over their extent (" << peak_pruned << " proved to fail it), ";
  if (shaving_propagations > 0)
    o << shaving_propagations << " shaving trials (" << shaving_cuts << " cut a slice), ";
  if (tube_bound_pieces > 0) o << tube_bound_pieces << " pieces of tubes' diameter-wall rectangles bounded, ";
  o << FormatNumber(seconds, 3) << " s\n";
  return o.str();
}

nlohmann::json Report::ToJson() const {
  nlohmann::json j;
  j["ok"] = found;
  j["status"] = ToString(status);
  j["message"] = message;
  j["objective"] = objective;
  j["objective_unit"] = objective_unit;
  j["design_variables"] = design_variables;
  if (found) {
    j["best"] = best;
    j["lower_bound"] = lower_bound;
    j["gap"] = gap;
  } else {
    j["best"] = nullptr;
    j["lower_bound"] = FiniteOrNull(lower_bound);
    j["gap"] = nullptr;
  }
  nlohmann::json d = nlohmann::json::array();
  for (const DesignValue& v : design) {
    nlohmann::json row = {{"name", v.name}, {"unit", v.unit}, {"value", v.value}, {"domain", {v.lower, v.upper}},
                          {"nominal", FiniteOrNull(v.nominal)}, {"at_bound", v.at_bound}};
    if (!tube_table.empty()) row["tube_size"] = v.tube_size;
    if (!v.same_as.empty()) row["same_as"] = v.same_as;
    d.push_back(row);
  }
  j["design"] = d;
  if (!tube_table.empty()) {
    nlohmann::json sizes = nlohmann::json::object();
    for (const auto& [component, size] : tube_sizes) sizes[component] = size;
    j["tube_sizes"] = {{"table", tube_table}, {"shafts", sizes}};
  }
  nlohmann::json a = nlohmann::json::array();
  for (const ActiveConstraint& c : active) a.push_back({{"label", c.label}, {"description", c.description}, {"text", c.text}});
  j["active_constraints"] = a;
  nlohmann::json m = nlohmann::json::array();
  for (const MassTerm& t : mass_terms)
    m.push_back({{"component", t.component},
                 {"law", t.law},
                 {"min", FiniteOrNull(t.lower)},
                 {"max", FiniteOrNull(t.upper)}});
  j["mass_terms"] = m;
  if (!infeasibility.empty()) j["explanation"] = infeasibility;
  if (!combinations.empty()) {
    nlohmann::json chosen = nlohmann::json::object();
    for (const auto& [component, designation] : parts) chosen[component] = designation;
    j["parts"] = chosen;
    nlohmann::json all = nlohmann::json::array();
    for (const Combination& k : combinations) {
      nlohmann::json row = {{"parts", k.designations}, {"status", k.status}};
      row["best"] = FiniteOrNull(k.best);
      row["lower_bound"] = FiniteOrNull(k.lower_bound);
      all.push_back(row);
    }
    j["combinations"] = all;
  }
  if (!pareto_objective.empty()) {
    nlohmann::json front = nlohmann::json::array();
    for (const ParetoPoint& p : pareto) {
      nlohmann::json d = nlohmann::json::object();
      for (const DesignValue& v : p.design) d[v.name] = v.value;
      front.push_back({{"epsilon", p.epsilon},
                       {"objective", FiniteOrNull(p.objective)},
                       {"lower_bound", FiniteOrNull(p.lower_bound)},
                       {"second", FiniteOrNull(p.second)},
                       {"status", p.status},
                       {"design", d}});
    }
    j["pareto"] = {{"objectives", {objective, pareto_objective}}, {"units", {objective_unit, pareto_unit}},
                   {"front", front}};
  }
  nlohmann::json rej = nlohmann::json::array();
  for (const auto& [what, n] : rejections) rej.push_back({{"check", what}, {"candidates", n}});
  j["rejections"] = rej;
  j["counters"] = {{"boxes", boxes},           {"pruned", pruned},
                   {"infeasible_boxes", infeasible_boxes}, {"candidates", candidates},
                   {"reduced_model_checks", reduced_model_checks}, {"improvements", improvements},
                   {"peak_checks", peak_checks}, {"peak_pruned", peak_pruned},
                   {"shaving_propagations", shaving_propagations}, {"shaving_cuts", shaving_cuts},
                   {"tube_bound_pieces", tube_bound_pieces}, {"seconds", seconds}};
  return j;
}

namespace {

/// SI from a display unit (the objectives' units are multiplicative: kg, kg*m^2, N*m).
double FromDisplay(double v, const std::string& unit) { return v / icsp::ToDisplay(1.0, unit); }

/// Branch over the part combinations (mixed radix over Options::choose_part), each combination's
/// continuous search cut off at the best design so far; the certified bound is the least bound of
/// the combinations (a combination proved infeasible or cut off bounds nothing below the best).
Report OptimizeOverParts(const Project& project, const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  double combinations = 1;
  for (const PartChoice& c : options.choose_part) combinations *= static_cast<double>(c.parts.size());
  if (combinations > options.max_part_combinations)
    throw InputError("optimize: " + FormatNumber(combinations, 6) + " combinations of parts for " +
                     std::to_string(options.choose_part.size()) + " --choose-part component(s), more than " +
                     std::to_string(options.max_part_combinations) +
                     " (max_part_combinations): choose parts for fewer components");
  Options inner = options;
  inner.choose_part.clear();
  Report best;
  bool have = false;
  double lower = kInf, best_si = kInf;
  int boxes = 0, pruned = 0, infeasible_boxes = 0, candidates = 0, checks = 0, improvements = 0, peak_checks = 0,
      peak_pruned = 0;
  bool limit = false;
  std::vector<std::size_t> index(options.choose_part.size(), 0);
  std::vector<Report::Combination> done;
  for (int k = 0; k < static_cast<int>(combinations); ++k) {
    Project p = project;
    Report::Combination combination;
    for (std::size_t i = 0; i < index.size(); ++i) {
      const PartOption& part = options.choose_part[i].parts[index[i]];
      ApplyPart(p, options.choose_part[i].component, part);
      combination.designations.push_back(part.designation);
    }
    for (std::size_t i = 0; i < index.size() && ++index[i] == options.choose_part[i].parts.size(); ++i) index[i] = 0;
    // The time left, shared by the combinations left.
    inner.max_seconds = (options.max_seconds - seconds()) / (combinations - k);
    if (inner.max_seconds <= 0.0) {  // out of time: this combination bounds nothing
      limit = true;
      combination.status = "not searched (time limit)";
      combination.best = combination.lower_bound = std::nan("");
      done.push_back(combination);
      lower = -kInf;
      continue;
    }
    if (options.prepare) options.prepare(p);
    detail::Optimizer o(p, inner);
    o.AllowNoDesignVariable();
    o.CutOff(best_si);
    Report r = o.Run();
    boxes += r.boxes, pruned += r.pruned, infeasible_boxes += r.infeasible_boxes, candidates += r.candidates;
    checks += r.reduced_model_checks, improvements += r.improvements, peak_checks += r.peak_checks;
    peak_pruned += r.peak_pruned;
    combination.status = r.message.rfind("cut off", 0) == 0 ? "cut off" : ToString(r.status);
    combination.best = r.found ? r.best : std::nan("");
    combination.lower_bound = r.lower_bound;
    done.push_back(combination);
    if (r.status == Status::kStoppedAtLimit || (r.status == Status::kNoDesignFound && combination.status != "cut off"))
      limit = limit || r.status == Status::kStoppedAtLimit || r.message.find("limit") != std::string::npos;
    if (r.status != Status::kInfeasible) lower = std::min(lower, FromDisplay(r.lower_bound, r.objective_unit));
    if (r.found) {
      best_si = FromDisplay(r.best, r.objective_unit);
      best = std::move(r);
      best.parts.clear();
      for (std::size_t i = 0; i < combination.designations.size(); ++i)
        best.parts.push_back({options.choose_part[i].component, combination.designations[i]});
      have = true;
    } else if (!have) {
      best = std::move(r);
    }
  }
  best.combinations = done;
  best.boxes = boxes, best.pruned = pruned, best.infeasible_boxes = infeasible_boxes, best.candidates = candidates;
  best.reduced_model_checks = checks, best.improvements = improvements, best.peak_checks = peak_checks;
  best.peak_pruned = peak_pruned;
  best.seconds = seconds();
  const Tolerance tol{options.relative_gap, options.absolute_gap};
  if (have) {
    lower = std::min(lower, best_si);
    best.lower_bound = icsp::ToDisplay(lower, best.objective_unit);
    best.gap = best_si != 0.0 ? (best_si - lower) / std::fabs(best_si) : best_si - lower;
    best.status = tol.Closed(best_si, lower) ? Status::kOptimal : Status::kStoppedAtLimit;
    best.message = std::to_string(done.size()) + " part combination(s) searched; " +
                   (best.status == Status::kOptimal ? "the gap closed within the tolerance" : "the gap is open");
  } else if (!limit && std::all_of(done.begin(), done.end(), [](const auto& c) { return c.status == "infeasible"; })) {
    best.status = Status::kInfeasible;
    best.message = "no part combination has a design that meets every requirement and margin (" +
                   std::to_string(done.size()) + " searched, each proved infeasible); the last one's explanation follows";
  } else {
    best.status = Status::kNoDesignFound;
    best.message = "no design found in " + std::to_string(done.size()) +
                   " part combination(s); this proves nothing for those not proved infeasible (see the combinations)";
  }
  return best;
}

/// The second objective's upper bound over the remaining domains at a design (the project with the
/// design fixed, no design variable left); NaN when it has none there.
double ObjectiveAt(const Project& project, const Options& options, const std::string& objective,
                   const std::vector<DesignValue>& design, double seconds) {
  std::vector<std::pair<std::string, double>> values;
  for (const DesignValue& d : design) values.push_back({d.name, d.value_si});
  Options o = options;
  o.objective = objective;
  o.design.clear();
  o.same_value.clear();  // the design, followers included, is fixed
  o.tube_sizes = {};  // the design is fixed: nothing left to restrict
  o.max_seconds = std::max(0.1, seconds);
  detail::Optimizer opt(FixDesign(project, values), o);
  opt.AllowNoDesignVariable();
  const Report r = opt.Run();
  return r.found ? r.best : std::nan("");
}

/// The front of two objectives by epsilon constraints (Options::pareto): OBJ2 alone, OBJ1 alone,
/// then OBJ1 under OBJ2 <= epsilon (a requirement added to the project) between the two.
Report OptimizePareto(const Project& project, const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  auto share = [&](int runs_left) {
    const double left = options.max_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::max(0.1, left / runs_left);
  };
  const int n = options.pareto_points;
  Options o = options;
  o.pareto.clear();
  Options o2 = o;
  o2.objective = options.pareto;
  o2.max_seconds = share(n + 2);
  const Report r2 = Optimize(project, o2);
  o.max_seconds = share(n + 1);
  Report out = Optimize(project, o);
  out.pareto_objective = options.pareto;
  out.pareto_unit = r2.objective_unit;
  if (!out.found || !r2.found) {
    if (!r2.found) out.message += "; the second objective '" + options.pareto + "' found no design: " + r2.message;
    return out;
  }
  const double lo = r2.best;
  double hi = ObjectiveAt(project, o, options.pareto, out.design, share(n + 1));
  if (!std::isfinite(hi) || hi < lo) hi = lo;
  std::vector<Report::ParetoPoint> points;
  for (int k = 0; k < n; ++k) {
    const double eps = lo + (hi - lo) * k / (n - 1);
    const double bound = eps + 1e-9 * std::fabs(eps);  // the written number rounds either way
    Project p = project;
    p.requirements.push_back({"pareto_epsilon",
                              options.pareto + " <= " + FormatNumber(bound, 12) +
                                  (out.pareto_unit.empty() ? "" : " " + out.pareto_unit),
                              "Pareto front: the second objective at most epsilon", {}});
    Options ok = o;
    ok.max_seconds = share(n - k);
    const Report r = Optimize(p, ok);
    Report::ParetoPoint pt;
    pt.epsilon = eps;
    pt.status = ToString(r.status);
    pt.objective = r.found ? r.best : std::nan("");
    pt.lower_bound = r.lower_bound;
    pt.second = r.found ? ObjectiveAt(project, o, options.pareto, r.design, share(n - k)) : std::nan("");
    pt.design = r.design;
    // By increasing epsilon the objective can only fall: a point no better than the last kept one
    // is not on the front.
    if (!r.found || (!points.empty() && !(pt.objective < points.back().objective))) continue;
    points.push_back(std::move(pt));
  }
  out.pareto = points;
  out.message += "; Pareto front of " + std::to_string(points.size()) + " point(s) over " + options.pareto + " in [" +
                 FormatNumber(lo, 6) + ", " + FormatNumber(hi, 6) + "] " + out.pareto_unit;
  return out;
}

}  // namespace

void ApplyPart(Project& project, const std::string& component, const PartOption& part) {
  Component* c = project.FindComponent(component);
  if (!c) throw InputError("part choice: no component '" + component + "' in the project");
  for (const auto& [name, value] : part.values) c->parameters[name] = value;
}

Report Optimize(const Project& project, const Options& options) {
  options.Validate();
  if (!options.pareto.empty()) return OptimizePareto(project, options);
  if (!options.choose_part.empty()) return OptimizeOverParts(project, options);
  detail::Optimizer o(project, options);
  return o.Run();
}

}  // namespace highlift::optimize
