// Synthesis: the design of least mass (or inertia, or any expression of the constraint language)
// that meets every requirement, parameter relation, setting rule and margin for every value of the
// remaining uncertain parameters, found by interval branch and bound with a certified lower bound.
//
//   optimize::Options o;
//   o.objective = "mass";
//   o.design = {"shaft_l1.wall_thickness", "stl_l1.lockout_torque_extend"};
//   const optimize::Report r = optimize::Optimize(project, o);
//   std::cout << r.BriefReport();   // "optimal: mass 41.2 kg in [41.19, 41.2] kg (gap 1e-7) ..."
//
// The constraints are the ones `highlift check` propagates (icsp's drive-system network: every
// component law, relation and requirement), plus every margin of that network >= 0 (limiter and
// brake settings, shaft capacity against drive torque). A design is accepted as an upper bound
// only when it is robustly feasible: with the design fixed and every other parameter over its
// whole domain, the interval evaluation of every constraint holds for certain, and (by default)
// `highlift size` and `highlift peak` (reduced_models) pass over the remaining domains. The method
// and its limits are in docs/optimize.md.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/componentdb/tube_sizes.h"
#include "highlift/core/project.h"

namespace highlift::optimize {

/// One part a component may be (a database row): the values it fixes, by parameter name (SI;
/// nominal and domain as the database gives them).
struct PartOption {
  std::string designation;                  ///< the database's designation, e.g. "TS-TI-45x1.8"
  std::map<std::string, Parameter> values;  ///< provenance database, database_part = designation
};

/// A discrete choice: `component` is one of `parts`.
struct PartChoice {
  std::string component;
  std::vector<PartOption> parts;
};

struct Options {
  /// "mass" (the torque shafts by their tube law, other components by their estimation laws),
  /// "inertia" (the sum of every component's inertia reflected to the PDU speed), or an
  /// expression of the constraint language over the quantities `check` knows
  /// ("shaft_l1.mass + 2 * shaft_l2.mass", "peak.jam_l1.torque").
  std::string objective = "mass";
  /// Design variables "component.parameter", in addition to the parameters the project marks
  /// with "design": true. Each needs a finite domain of positive width.
  std::vector<std::string> design;
  /// Parameters that take one value together: identical parts (every geared rotary actuator of a
  /// drive line has one ratio, or the flaps it drives would not move together). Each group is one
  /// design variable: its first name (added to the design variables when it is not one), which
  /// the others follow exactly through a law `other == first` of the constraint network (so they
  /// are neither uncertain parameters nor design variables of their own); its domain is the
  /// intersection of the group's domains. The design, the written project and `size` and `peak`
  /// give every member the value. Each group names at least two parameters, each name in one
  /// group. Empty by default.
  std::vector<std::vector<std::string>> same_value;
  int max_boxes = 20000;            ///< stop (kStoppedAtLimit) after processing this many boxes
  double relative_gap = 1e-6;       ///< stop when (best - lower bound) <= relative_gap * |best|
  double absolute_gap = 1e-12;      ///< ... or when best - lower bound <= absolute_gap (SI units)
  double max_seconds = 60.0;        ///< stop (kStoppedAtLimit) after this wall time [s]
  int line_search_steps = 6;        ///< bisection steps of the local search in each box (each step
                                    ///< is one robust feasibility check)
  /// The polish of the incumbent (docs/optimize.md, Method 3), after a coordinate search once a
  /// tenth of max_seconds has passed, and at the end: a pattern search from the best design, each
  /// design variable towards less objective and each pair of one component's variables traded
  /// (one lighter, the other heavier by half the objective saved: a tube's wall for its diameter),
  /// steps from 1/16 down to 1e-3 of each domain, with at most this many robust checks (the same
  /// check as every candidate) and a fifth of max_seconds per call. 0: no polish. Not with
  /// tube_sizes.
  int polish_evaluations = 3000;
  /// Resizing the incumbent's tubes (docs/optimize.md, Method 3), before each coordinate search:
  /// each tube whose outer diameter and wall are both design variables sized alone to the lightest
  /// that meets every check reading it with the loads of the design held, all tubes at once, then
  /// checked as every candidate; again with the new design's loads, up to this many times. 0: none.
  int resize_iterations = 6;
  /// The tubes' own lower bound (docs/optimize.md, Method 2): in every box, each tube whose outer
  /// diameter and wall are both design variables gets its diameter-wall rectangle paved best
  /// first, each piece kept unless a check reading the tube fails at every point of it (the loads
  /// at their enclosures over the box), until the lightest kept piece is within a tenth of
  /// relative_gap or this many pieces were split; the lightest kept piece's mass is a certified
  /// lower bound of the tube's term, and the kept pieces' hull contracts its diameter and wall.
  /// HC4 and shaving see one constraint at a time, and a tube's capacity min(tau_allow, tau_cr)
  /// 2 Ip / D against its mass is a curve in (D, t), not a box. 0: none. Not with tube_sizes.
  int tube_bound_splits = 256;
  double propagation_ratio = 0.01;  ///< HC4 agenda ratio of the contractor (docs/icsp.md; 0: exact
                                    ///< fixed point, slower, same certificates)
  /// Lower bounds by shaving (3B consistency on the objective, as IbexOpt's lower bounding by
  /// contraction): in every box, once a design is known, each term of the objective (each
  /// component's mass or reflected inertia) gets up to this many trials "term <= its lower bound +
  /// a slice" (a propagation each); a slice the propagation empties is cut off for certain, which
  /// raises the term's lower bound, inherited by the box's children. Then the objective itself gets
  /// as many trials. 0: plain HC4 bounds (docs/optimize.md, Method 2).
  int shaving_tries = 2;
  double shaving_ratio = 0.01;      ///< HC4 agenda ratio of the shaving trials' propagations
  /// The robust check's enclosure of a law y == h(m, s) whose factors share arguments (the peak
  /// torque of a jam or rupture, w w1 J*: the eigenfrequency w1 falls and J* rises with every
  /// inertia): when a requirement that reads y is not certain, y is enclosed again as the union of h
  /// over a partition of the shared arguments, with up to this many bisections per law (two
  /// black-box evaluations each). 0: plain interval evaluation (docs/optimize.md, Method 1).
  int dependency_splits = 8;
  bool verify_size = true;          ///< an upper bound must also pass reduced_models' Size over the
                                    ///< remaining domains (`highlift size` exits 0 for it)
  bool verify_peak = true;          ///< ... and AnalysePeaks (`highlift peak` exits 0 for it)
  /// Discrete choices (`--choose-part COMPONENT`): each listed component is one of its parts. The
  /// search branches over the combinations first (each one's project: the parts' values fixed,
  /// then `prepare`), best root bound first, each combination's continuous branch and bound cut off
  /// at the best design of the others; the lower bound is the least over the combinations. With
  /// choices, the design variables may be none (a pure part choice).
  std::vector<PartChoice> choose_part;
  int max_part_combinations = 512;  ///< more combinations than this is an InputError
  /// Applied to each combination's project before its search (the CLI: the estimator, so that
  /// what a part's values imply, e.g. an inertia from a rating, follows the part). Default: none.
  std::function<void(Project&)> prepare;
  /// `--pareto OBJ1,OBJ2`: the second objective, an expression of the constraint language (the
  /// first is `objective`). Optimize then traces the front by epsilon constraints: OBJ2 alone at
  /// its least, OBJ1 alone (and OBJ2 at its design), then OBJ1 least under OBJ2 <= epsilon for
  /// pareto_points values of epsilon evenly between the two; max_seconds is shared by the runs.
  std::string pareto;
  int pareto_points = 5;  ///< epsilon values (2 to 50), the ends included
  /// `--tube-sizes`: every torque shaft whose outer_diameter and/or wall_thickness are design
  /// variables is made of one of these sizes (those within its domains; with one of the two a
  /// design variable, the sizes whose other value lies in the other's domain). A table
  /// constraint of the branch and bound: each box's (D, t) contracted to the hull of the sizes
  /// inside it, candidate designs snapped to sizes. Empty (the default): D and t are continuous.
  /// componentdb::StandardTubeSizes() is the shipped ISO 3 R20 table.
  componentdb::TubeSizeTable tube_sizes;
  /// Throws InputError naming the bad option and the remedy.
  void Validate() const;
};

enum class Status : std::uint8_t {
  kOptimal,          ///< a robustly feasible design within the gap tolerance of the lower bound
  kStoppedAtLimit,   ///< a robustly feasible design, gap still open (boxes or time ran out)
  kInfeasible,       ///< proved: no design in the domains meets the constraints
  kNoDesignFound,    ///< gave up (limit reached) without a robustly feasible design; not a proof
};
/// "optimal", "stopped_at_limit", "infeasible", "no_design_found".
std::string ToString(Status s);
std::optional<Status> StatusFromString(const std::string& s);

/// One design variable at the optimum.
struct DesignValue {
  std::string name;         ///< "component.parameter"
  std::string unit;         ///< display unit of the numbers below
  double value = 0.0;       ///< at the best design (display unit)
  double value_si = 0.0;    ///< the same in SI (what FixDesign takes)
  double lower = 0.0;       ///< domain in the project (display unit)
  double upper = 0.0;
  double nominal = 0.0;     ///< the project's nominal value (NaN when it has none)
  std::string at_bound;     ///< "lower", "upper" or "" (the domain limits the design)
  std::string tube_size;    ///< with Options::tube_sizes: the size of this shaft's D and t, e.g. "45x1.8"
  std::string same_as;      ///< Options::same_value: the design variable this parameter follows ("" for one)
};

/// A constraint that limits the design: at the best design it holds, a small step towards a
/// smaller objective breaks it.
struct ActiveConstraint {
  std::string label;        ///< requirement id, "margin:<quantity>", a law's label, "size", "peak"
  std::string description;  ///< in words
  std::string text;         ///< the constraint as written (units), or the analysis' message
};

/// One term of the mass objective.
struct MassTerm {
  std::string component;
  std::string law;          ///< e.g. "tube law m = rho pi (D - t) t L", or why it is not counted
  double lower = 0.0;       ///< kg over the remaining domains at the best design (NaN: not counted)
  double upper = 0.0;
};

struct Report {
  Status status = Status::kNoDesignFound;
  std::string message;
  std::string objective;        ///< as given
  std::string objective_unit;   ///< display unit of best / lower_bound
  std::vector<std::string> design_variables;
  bool found = false;           ///< a robustly feasible design was found
  double best = 0.0;            ///< objective of the best design: its upper bound over the remaining
                                ///< uncertain parameters (display unit)
  double lower_bound = 0.0;     ///< certified: no robustly feasible design has a smaller objective
  double gap = 0.0;             ///< (best - lower_bound) / |best|
  std::vector<DesignValue> design;
  std::vector<ActiveConstraint> active;
  std::vector<MassTerm> mass_terms;  ///< objective "mass": where each component's mass comes from
  std::string infeasibility;    ///< kInfeasible: check's explanation of the conflict
  /// With part choices: the chosen part per component (of the best design), and every combination
  /// searched with its outcome ("optimal", "infeasible", "cut off", ...) and bounds.
  std::vector<std::pair<std::string, std::string>> parts;
  struct Combination {
    std::vector<std::string> designations;  ///< in the order of Options::choose_part
    std::string status;
    double best = 0.0;                      ///< NaN when no design
    double lower_bound = 0.0;
  };
  std::vector<Combination> combinations;
  /// With Options::tube_sizes: the table's name ("standard" or its file) and the size of each shaft
  /// restricted to it (of the best design), by component.
  std::string tube_table;
  std::vector<std::pair<std::string, std::string>> tube_sizes;
  /// With Options::pareto: the front, by increasing epsilon; each point the best OBJ1 design
  /// under OBJ2 <= epsilon (points that were no better than a neighbour are dropped).
  struct ParetoPoint {
    double epsilon = 0.0;      ///< the bound on OBJ2 (its display unit)
    double objective = 0.0;    ///< OBJ1 at the design (upper bound over the remaining domains)
    double lower_bound = 0.0;  ///< OBJ1's certified bound under OBJ2 <= epsilon
    double second = 0.0;       ///< OBJ2 at the design (upper bound over the remaining domains)
    std::string status;
    std::vector<DesignValue> design;
  };
  std::string pareto_objective, pareto_unit;
  std::vector<ParetoPoint> pareto;
  /// Why candidate designs were rejected: the first failing constraint (label) or size/peak item,
  /// with how many candidates it rejected, most frequent first (at most 5).
  std::vector<std::pair<std::string, int>> rejections;
  // Counters.
  int boxes = 0;                ///< boxes processed
  int pruned = 0;               ///< boxes whose lower bound exceeded the best design
  int infeasible_boxes = 0;     ///< boxes the contractor emptied
  int candidates = 0;           ///< robust feasibility checks (each one model evaluation)
  int reduced_model_checks = 0; ///< candidates that went on to Size and AnalysePeaks
  int improvements = 0;         ///< times the best design improved
  int peak_checks = 0;          ///< boxes analysed by `peak` over their whole extent
  int peak_pruned = 0;          ///< ... of which `peak` proved that none of their designs passes it
  int shaving_propagations = 0;  ///< trial propagations of the shaving (Options::shaving_tries)
  int shaving_cuts = 0;         ///< ... of which proved a slice empty (a raised lower bound)
  int tube_bound_pieces = 0;    ///< pieces of the tubes' diameter-wall rectangles examined (Options::tube_bound_splits)
  /// The certified lower bound of the root box: after HC4 and shaving with the first design known
  /// (or HC4 alone when none was found); display unit.
  double root_lower_bound = 0.0;
  double seconds = 0.0;
  /// The project with the design variables fixed at the best design (nominal and domain, provenance
  /// "optimized"); only when found.
  std::optional<Project> design_project;

  /// One line: "optimal: mass 41.2 kg, certified >= 41.19 kg (gap 2e-7), 812 boxes in 1.3 s".
  std::string BriefReport() const;
  /// The design table, the active constraints, the mass terms and the counters.
  std::string FullReport() const;
  nlohmann::json ToJson() const;
};

/// Minimizes the objective over the design variables. `project` holds the domains (the CLI first
/// runs the estimator, as `check` does). Throws InputError for bad input: no design variable, a
/// design variable that is not a parameter or has no finite domain, an objective that does not
/// parse or is unbounded over the domains. Infeasibility and running out of limits are statuses.
Report Optimize(const Project& project, const Options& options = {});

namespace detail {
class Optimizer;
}

/// One design point checked as Optimize checks its candidates (robust interval check, then size
/// and peak): for baselines (random search in bench/optimize) and for tools that propose designs.
struct PointCheck {
  bool feasible = false;
  double objective = 0.0;    ///< upper bound over the remaining domains (display unit); +inf if none
  std::string failure;       ///< the first constraint that does not hold for certain, or size/peak's
};

class DesignEvaluator {
 public:
  /// Builds the network once (the same setup as Optimize; the same InputErrors).
  DesignEvaluator(const Project& project, const Options& options);
  ~DesignEvaluator();
  DesignEvaluator(const DesignEvaluator&) = delete;
  DesignEvaluator& operator=(const DesignEvaluator&) = delete;
  /// The design variables ("component.parameter") and their domains (SI), in the order Check takes.
  const std::vector<std::string>& variables() const;
  std::vector<std::pair<double, double>> domains() const;
  /// `x` in SI, one value per variable; checked as given (with Options::tube_sizes, not snapped to
  /// a size).
  PointCheck Check(const std::vector<double>& x);

 private:
  std::unique_ptr<detail::Optimizer> impl_;
};

/// `project` with `component`'s parameters set to the part's values (provenance database). Throws
/// InputError when the project has no such component.
void ApplyPart(Project& project, const std::string& component, const PartOption& part);

/// `project` with each named parameter fixed at its value (SI): nominal and a point domain,
/// provenance "optimized". Throws InputError for a name that is not a parameter of the project.
Project FixDesign(const Project& project, const std::vector<std::pair<std::string, double>>& values);

}  // namespace highlift::optimize
