#include "highlift/reduced_models/analyses.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <memory>
#include <cmath>
#include <limits>
#include <functional>
#include <iterator>
#include <numbers>
#include <optional>
#include <set>

#include "graph_model.h"
#include "laws.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/model/hydraulic_pdu.h"
#include "highlift/reduced_models/modal.h"
#include "highlift/reduced_models/sampling.h"
#include "highlift/reduced_models/single_dof.h"
#include "torque_flow.h"

namespace highlift::reduced_models {
namespace {

using detail::Interval;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEigenSlack = 1e-9;  // relative widening of corner eigenvalues for round-off

std::string Fmt(double v, int digits = 4) { return FormatNumber(v, digits); }
double Hz(double omega) { return omega / (2.0 * std::numbers::pi); }

int ElementsOf(const Project& project, int requested) {
  return requested > 0 ? requested : project.settings.shaft_elements;
}

Transmission Nominal(const detail::TransmissionDraft<double>& d) {
  return d.Project([](double x) { return x; }, [](double x) { return x; });
}

}  // namespace

LumpedModel BuildProjectModel(const Project& project, Reduction reduction, int elements_per_segment) {
  const detail::Graph g = detail::BuildGraph(project);
  return BuildLumpedModel(Nominal(detail::BuildTransmission<double>(g, {})), reduction,
                          ElementsOf(project, elements_per_segment));
}

double FirstEigenfrequency(const Project& project) {
  const detail::Graph g = detail::BuildGraph(project);
  const auto draft = detail::BuildTransmission<double>(g, {});
  const LumpedModel m = BuildLumpedModel(Nominal(draft), Reduction::kFullResolution, project.settings.shaft_elements);
  return ComputeModes(m, {{m.NodeOfPoint(draft.point_of_node[0])}, 0}).FirstElasticOmega();
}

ModesReport AnalyseModes(const Project& project, const ModesOptions& options) {
  const detail::Graph g = detail::BuildGraph(project);
  const auto draft = detail::BuildTransmission<double>(g, {});
  const Transmission t = Nominal(draft);
  ModesReport report;
  report.project = project.name;
  report.elements_per_segment = ElementsOf(project, options.elements_per_segment);
  for (Reduction rule : {Reduction::kFullResolution, Reduction::kAccumulated, Reduction::kTwoMassesPerSection}) {
    const LumpedModel m = BuildLumpedModel(t, rule, report.elements_per_segment);
    ModelModes mm;
    mm.reduction = rule;
    mm.degrees_of_freedom = static_cast<int>(m.nodes.size());
    const ModalResult free = ComputeModes(m, {{}, 0});
    for (std::size_t k = free.rigid_body_modes; k < free.omega.size() && mm.free_hz.size() < static_cast<std::size_t>(options.modes); ++k)
      mm.free_hz.push_back(Hz(free.omega[k]));
    const int pdu = m.NodeOfPoint(draft.point_of_node[0]);
    const ModalResult clamped = ComputeModes(m, {{pdu}, options.modes});
    for (int k = 0; k < static_cast<int>(clamped.omega.size()) && k < options.modes; ++k) {
      mm.clamped_hz.push_back(Hz(clamped.omega[k]));
      std::vector<double> shape(m.nodes.size());
      const double largest = std::max(clamped.shapes.col(k).cwiseAbs().maxCoeff(), 1e-300);
      for (std::size_t i = 0; i < m.nodes.size(); ++i) shape[i] = clamped.shapes(static_cast<Eigen::Index>(i), k) / largest;
      mm.clamped_shapes.push_back(std::move(shape));
    }
    for (const auto& node : m.nodes) mm.node_names.push_back(node.name);
    report.models.push_back(std::move(mm));
  }
  const ModelModes& full = report.models[0];
  for (ModelModes& mm : report.models) {
    if (!full.free_hz.empty() && !mm.free_hz.empty()) mm.first_free_error = mm.free_hz[0] / full.free_hz[0] - 1.0;
    if (!full.clamped_hz.empty() && !mm.clamped_hz.empty())
      mm.first_clamped_error = mm.clamped_hz[0] / full.clamped_hz[0] - 1.0;
  }
  return report;
}

std::string ModesReport::BriefReport() const {
  std::string out = "modes of '" + project + "':";
  for (const auto& m : models)
    out += " " + ToString(m.reduction) + " " + std::to_string(m.degrees_of_freedom) + " DOF first " +
           (m.free_hz.empty() ? std::string("-") : Fmt(m.free_hz[0])) + " Hz free, " +
           (m.clamped_hz.empty() ? std::string("-") : Fmt(m.clamped_hz[0])) + " Hz PDU clamped;";
  return out;
}

std::string ModesReport::FullReport() const {
  std::string out = "Lumped models and modes: " + project + " (full resolution: " +
                    std::to_string(elements_per_segment) + " sub-elements per shaft segment)\n";
  TextTable table({"model", "DOF", "free modes [Hz]", "first error", "PDU clamped [Hz]", "first error"}, {1, 3, 5});
  for (const auto& m : models) {
    auto list = [](const std::vector<double>& v) {
      std::string s;
      for (double x : v) s += (s.empty() ? "" : ", ") + Fmt(x);
      return s;
    };
    table.AddRow({ToString(m.reduction), std::to_string(m.degrees_of_freedom), list(m.free_hz),
                  Fmt(100.0 * m.first_free_error, 3) + " %", list(m.clamped_hz), Fmt(100.0 * m.first_clamped_error, 3) + " %"});
  }
  return out + table.ToString();
}

nlohmann::json ModesReport::ToJson() const {
  nlohmann::json j = {{"project", project}, {"elements_per_segment", elements_per_segment}};
  j["models"] = nlohmann::json::array();
  for (const auto& m : models)
    j["models"].push_back({{"reduction", ToString(m.reduction)}, {"degrees_of_freedom", m.degrees_of_freedom},
                           {"free_hz", m.free_hz}, {"clamped_hz", m.clamped_hz},
                           {"first_free_error", m.first_free_error}, {"first_clamped_error", m.first_clamped_error},
                           {"nodes", m.node_names}, {"clamped_shapes", m.clamped_shapes}});
  return j;
}

// ---------------------------------------------------------------------------------------------
// Peak loads

namespace {

struct Focus {
  int root = -1;                       ///< graph node the part starts at (-1: whole graph)
  int stop = -1;                       ///< graph node held fixed
};

/// Single-DOF oscillator of the part in focus at nominal values, with its first mode.
struct FocusModel {
  detail::TransmissionDraft<double> draft;
  LumpedModel model;
  SingleDof oscillator;
  Eigen::VectorXd phi;                 ///< first mode, mass-normalised, over the model nodes
  int stop_node = -1;
};

FocusModel Reduce(const detail::Graph& g, const Focus& f, int elements) {
  FocusModel fm;
  fm.draft = detail::BuildTransmission<double>(g, {}, f.root);
  fm.model = BuildLumpedModel(Nominal(fm.draft), Reduction::kFullResolution, elements);
  fm.stop_node = fm.model.NodeOfPoint(fm.draft.point_of_node[f.stop]);
  fm.oscillator = ReduceToSingleDof(fm.model, {fm.stop_node});
  fm.phi = ComputeModes(fm.model, {{fm.stop_node}, 1}).shapes.col(0);
  return fm;
}

/// Whether the part in focus has an inertia the stop does not hold rigidly. Beyond the rupture of
/// the last shaft there may be only what is bolted to the wing-tip brake (a position sensor): that
/// part does not move, has no dynamic peak and is no case.
bool HasFreeInertia(const detail::Graph& g, const Focus& f, int elements) {
  const auto draft = detail::BuildTransmission<double>(g, {}, f.root);
  const LumpedModel model = BuildLumpedModel(Nominal(draft), Reduction::kFullResolution, elements);
  const int stop = model.NodeOfPoint(draft.point_of_node[f.stop]);
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    if (static_cast<int>(i) != stop && model.nodes[i].J > 0.0) return true;
  return false;
}

/// Enclosure of (w1, J*) over the parameter domains: w1 is monotone (rises with every c, falls
/// with every J) and J* rises with every J, so the soft-heavy and stiff-light corners bound them.
void Enclose(const detail::Graph& g, const Focus& f, int elements, const detail::ParameterMode& mode, Interval* omega,
             Interval* J_star) {
  const auto wide = detail::BuildTransmission<Interval>(g, mode, f.root);
  const auto soft_heavy = wide.Project([](const Interval& x) { return x.hi; }, [](const Interval& x) { return x.lo; });
  const auto stiff_light = wide.Project([](const Interval& x) { return x.lo; }, [](const Interval& x) { return x.hi; });
  const LumpedModel heavy = BuildLumpedModel(soft_heavy, Reduction::kFullResolution, elements);
  const LumpedModel light = BuildLumpedModel(stiff_light, Reduction::kFullResolution, elements);
  const int stop = heavy.NodeOfPoint(wide.point_of_node[f.stop]);
  ModalOptions modal;
  modal.clamped = {stop};
  modal.mode_shapes = 0;
  const double omega_lo = ComputeModes(heavy, modal).FirstElasticOmega();
  const double omega_hi = ComputeModes(light, modal).FirstElasticOmega();
  double J_lo = 0.0, J_hi = 0.0;
  for (std::size_t i = 0; i < heavy.nodes.size(); ++i)
    if (static_cast<int>(i) != stop) {
      J_hi += heavy.nodes[i].J;
      J_lo += light.nodes[i].J;
    }
  *omega = Interval(omega_lo * (1 - kEigenSlack), omega_hi * (1 + kEigenSlack));
  *J_star = Interval(J_lo * (1 - kEigenSlack), J_hi * (1 + kEigenSlack));
}

/// Bitwise the same doubles (a signed zero or a NaN compares as its bits).
bool SameBits(const Interval& a, const Interval& b) {
  return std::bit_cast<std::uint64_t>(a.lo) == std::bit_cast<std::uint64_t>(b.lo) &&
         std::bit_cast<std::uint64_t>(a.hi) == std::bit_cast<std::uint64_t>(b.hi);
}
bool SameBits(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const Interval& x, const Interval& y) {
           return SameBits(x, y);
         });
}
bool SameBits(const detail::Flow<Interval>& a, const detail::Flow<Interval>& b) {
  return SameBits(a.tau_in, b.tau_in) && SameBits(a.w_in, b.w_in) && SameBits(a.n, b.n);
}

/// Values of one mode that the single-parameter modes share with the nominal mode where theirs
/// are the same doubles: most of the several hundred parameters change one node's inertia or
/// stiffness, or only a timing, and a copy of every vector per parameter was the largest part
/// of the process's peak memory (issue 30). Read-only once made.
template <class T>
class Shared {
 public:
  Shared() = default;
  /// `value`, or `same`'s storage when `same` holds the same doubles bit for bit.
  explicit Shared(T value, const Shared* same = nullptr) {
    if (same != nullptr && same->value_ && SameBits(*same->value_, value)) {
      value_ = same->value_;
    } else {
      value_ = std::make_shared<const T>(std::move(value));
    }
  }
  const T& operator*() const { return *value_; }
  const T* operator->() const { return value_.get(); }
  const T* get() const { return value_.get(); }

 private:
  std::shared_ptr<const T> value_;
};

/// Per-node intervals (`values[i]` reads node i).
class NodeValues : public Shared<std::vector<Interval>> {
 public:
  using Shared<std::vector<Interval>>::Shared;
  const Interval& operator[](std::size_t i) const { return (**this)[i]; }
};

/// Per graph node, what the reduced models read of it (reflected to the PDU speed), and the
/// steady flows the rupture speed needs, for one parameter mode. Computed once per mode; a
/// single-parameter mode shares what its parameter leaves as the nominal mode's.
struct ModeData {
  detail::ParameterMode mode;
  NodeValues n;       ///< speed ratio of the node's input to the PDU output
  NodeValues J;       ///< concentrated inertia of the node
  NodeValues link_c;  ///< stiffness of the node's link (shaft or elastic component), 0 if rigid
  NodeValues link_J;  ///< distributed inertia of a shaft
  Shared<detail::Flow<Interval>> back;  ///< aiding airloads, no friction
  Shared<detail::Flow<Interval>> drag;  ///< friction only
};

/// Parameters that only change the monitor and brake timing, or only inertias and stiffnesses:
/// a single-parameter evaluation reuses the nominal values of what they cannot change.
bool TimingOnly(const std::string& name) {
  return name == "engagement_latency" || name == "time_to_max_torque" || name == "latency" ||
         name == "asymmetry_threshold" || name == "overspeed_factor" || name == "max_output_speed";
}
bool InertiaOrStiffnessOnly(const std::string& name) {
  return name == "inertia" || name == "input_inertia" || name == "load_inertia" || name == "motor_inertia" ||
         name == "gear_inertia" || name == "stiffness" || name == "stiffness_normal" || name == "shear_modulus" ||
         name == "density" || name == "linear_density";
}

bool FrictionOnly(const std::string& name) {
  return name == "coulomb_torque" || name == "viscous_coefficient" || name == "stribeck_torque" ||
         name == "stribeck_decay" || name == "drag_per_length";
}

ModeData Evaluate(const detail::Graph& g, const detail::ParameterMode& mode, const std::map<std::string, double>& aiding,
                  const Interval& w, const ModeData* nominal = nullptr) {
  using Flow = Shared<detail::Flow<Interval>>;
  if (nominal && (TimingOnly(mode.parameter) || FrictionOnly(mode.parameter))) {
    ModeData d = *nominal;  // shares every value
    d.mode = mode;
    // Friction changes only the drag flow (the back-drive flow is computed without friction).
    // (A friction coefficient is no gear ratio: the speed ratios are the nominal mode's.)
    if (FrictionOnly(mode.parameter))
      d.drag = Flow(detail::SolveFlow<Interval>(g, mode, {}, w, true, nominal->drag.get(), &*nominal->n), &nominal->drag);
    return d;
  }
  ModeData d;
  d.mode = mode;
  std::vector<Interval> n = detail::SpeedRatios<Interval>(g, mode);
  const std::size_t count = g.nodes.size();
  std::vector<Interval> J(count, Interval(0.0)), link_c(count, Interval(0.0)), link_J(count, Interval(0.0));
  for (std::size_t i = 0; i < count; ++i) {
    const Component& c = *g.nodes[i].component;
    // One parameter spans its domain: every other component's lumped values are the nominal
    // mode's, the same operations on the same doubles, where its speed ratio is the same too.
    if (nominal && mode.kind == detail::ParameterMode::kOne && c.id != mode.component &&
        detail::SameValue(n[i], nominal->n[i])) {
      J[i] = nominal->J[i];
      link_c[i] = nominal->link_c[i];
      link_J[i] = nominal->link_J[i];
      continue;
    }
    const Interval n2 = n[i] * n[i];
    const model::ComponentModel* m = g.nodes[i].model;
    const model::Lumped<Interval> lumped = detail::LumpedOf<Interval>(c, mode, m);
    if (m && m->roles().segment) {
      link_c[i] = *lumped.c * n2;
      link_J[i] = lumped.J * n2;
      continue;
    }
    J[i] = lumped.J * n2;
    if (lumped.c) link_c[i] = *lumped.c * n2;
  }
  d.n = NodeValues(std::move(n), nominal ? &nominal->n : nullptr);
  d.J = NodeValues(std::move(J), nominal ? &nominal->J : nullptr);
  d.link_c = NodeValues(std::move(link_c), nominal ? &nominal->link_c : nullptr);
  d.link_J = NodeValues(std::move(link_J), nominal ? &nominal->link_J : nullptr);
  if (nominal && InertiaOrStiffnessOnly(mode.parameter)) {
    d.back = nominal->back;
    d.drag = nominal->drag;
    return d;
  }
  // The flows' speed ratios are this mode's, computed above.
  d.back = Flow(detail::SolveFlow<Interval>(g, mode, aiding, w, false, nominal ? nominal->back.get() : nullptr, &*d.n),
                nominal ? &nominal->back : nullptr);
  d.drag = Flow(detail::SolveFlow<Interval>(g, mode, {}, w, true, nominal ? nominal->drag.get() : nullptr, &*d.n),
                nominal ? &nominal->drag : nullptr);
  return d;
}

/// First-order share of each uncertain parameter in the width of tau = w w1 J*: modal
/// sensitivities d(w1^2)/dc = (dphi)^2, d(w1^2)/dJ_i = -w1^2 phi_i^2 (mass-normalised phi),
/// times the widths of the reflected c and J when only that parameter spans its domain.
///
/// A parameter contributes only where its mode's value is not the nominal mode's: a value it leaves
/// as it was (the same bits) has the nominal mode's width, which is outward rounding of a point,
/// not uncertainty; likewise the rupture speed's width beyond the nominal mode's own. A parameter
/// that changes nothing of the case is not ranked.
std::vector<ParameterShare> Rank(const detail::Graph& g, const Focus& f, const FocusModel& fm, double w,
                                 const ModeData& nominal, const std::vector<ModeData>& singles,
                                 const std::function<double(const ModeData&)>& w_width) {
  const LumpedModel& m = fm.model;
  const double omega = fm.oscillator.omega, J = fm.oscillator.J_star;
  std::vector<double> dJ(m.nodes.size(), 0.0), dc(m.springs.size(), 0.0);
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (static_cast<int>(i) != fm.stop_node) dJ[i] = w * (omega - J * omega * fm.phi[i] * fm.phi[i] / 2.0);
  for (std::size_t s = 0; s < m.springs.size(); ++s) {
    const auto& spring = m.springs[s];
    const double d = fm.phi[spring.a] - (spring.b >= 0 ? fm.phi[spring.b] : 0.0);
    dc[s] = w * J * d * d / (2.0 * omega);
  }
  // Per transmission point: d tau / d J_point; per link: d tau / d c_link (all its springs
  // carry n c) and d tau / d J_link (J/n per element, halves at the element ends).
  std::vector<double> dJ_point(fm.draft.points.size(), 0.0), dc_link(fm.draft.links.size(), 0.0),
      dJ_link(fm.draft.links.size(), 0.0);
  for (std::size_t p = 0; p < fm.draft.points.size(); ++p) {
    const int node = m.NodeOfPoint(static_cast<int>(p));
    if (node >= 0) dJ_point[p] = dJ[node];
  }
  std::vector<int> springs_of_link(fm.draft.links.size(), 0);
  for (const auto& spring : m.springs)
    if (spring.link >= 0) ++springs_of_link[spring.link];
  for (std::size_t s = 0; s < m.springs.size(); ++s) {
    const int l = m.springs[s].link;
    if (l < 0) continue;
    const double k = springs_of_link[l];
    dc_link[l] += dc[s] * k;
    dJ_link[l] += 0.5 * (dJ[m.springs[s].a] + (m.springs[s].b >= 0 ? dJ[m.springs[s].b] : 0.0)) / k;
  }
  std::vector<bool> in_focus(g.nodes.size(), f.root < 0);
  if (f.root >= 0)
    for (int i : g.Subtree(f.root)) in_focus[i] = true;
  std::vector<ParameterShare> out;
  double total = 0.0;
  // The width of `value` where it is not `base`'s (the same bits: 0).
  const auto changed = [](const Interval& value, const Interval& base) {
    return SameBits(value, base) ? 0.0 : value.width();
  };
  const double w_width_nominal = w_width ? w_width(nominal) : 0.0;
  for (const ModeData& one : singles) {
    double width = 0.0;
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      if (!in_focus[i]) continue;
      const int p = fm.draft.point_of_node[i];
      const int l = fm.draft.link_of_node[i];
      if (p >= 0) width += std::abs(dJ_point[p]) * changed(one.J[i], nominal.J[i]);
      if (l >= 0)
        width += std::abs(dc_link[l]) * changed(one.link_c[i], nominal.link_c[i]) +
                 std::abs(dJ_link[l]) * changed(one.link_J[i], nominal.link_J[i]);
    }
    if (w_width) width += omega * J * std::max(0.0, w_width(one) - w_width_nominal);
    if (width > 0.0) {
      out.push_back({one.mode.component + "." + one.mode.parameter, width, 0.0});
      total += width;
    }
  }
  for (auto& p : out) p.share = p.width / total;
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.width > b.width; });
  return out;
}

const Component* FindSensor(const detail::Graph& g, const std::vector<int>& nodes) {
  for (int i : nodes)
    if (g.Roles(i).tip_sensor) return g.nodes[i].component;
  for (const auto& n : g.nodes)
    if (RolesOf(n.component->type).tip_sensor) return n.component;
  return nullptr;
}

}  // namespace

PeakReport AnalysePeaks(const Project& project, const PeakOptions& options) {
  const detail::Graph g = detail::BuildGraph(project);
  const Component& pdu = *g.nodes[0].component;
  const int elements = std::max(1, options.elements_per_segment);
  const detail::ParameterMode nominal, all{detail::ParameterMode::kIntervals, {}, {}};
  PeakReport report;
  report.project = project.name;
  report.reduction = "full resolution, " + std::to_string(elements) + " element(s) per shaft segment";
  if (project.load_cases.empty())
    throw InputError("project '" + project.name + "' has no load cases; the peak loads need the operating speed and "
                     "the airloads: add a load case under \"load_cases\"");

  // Operating speed and the largest airload magnitudes over the load cases, as aiding loads.
  // (With intervals, the speeds are enclosures over the PDU's max_output_speed domain where a
  // load case has no speed profile.)
  double w_operating = 0.0;
  Interval w_operating_all(0.0);
  std::map<std::string, double> aiding;
  for (const LoadCase& lc : project.load_cases) {
    w_operating = std::max(w_operating, detail::SizingSpeed(lc, pdu));
    if (options.intervals) w_operating_all = detail::Max(w_operating_all, detail::SizingSpeed<Interval>(lc, pdu, all));
    for (const auto& [actuator, value] : detail::SizingLoads(lc))
      aiding[actuator] = std::min(aiding[actuator], -std::abs(value));
  }
  if (!options.intervals) w_operating_all = Interval(w_operating);
  const bool has_reference = detail::HasValue(pdu, "max_output_speed");
  const double w_reference = has_reference ? detail::NominalValue(pdu, "max_output_speed") : w_operating;
  const Interval w_reference_all =
      has_reference && options.intervals ? detail::Read<Interval>(pdu, "max_output_speed", all) : Interval(w_reference);
  const auto speed_ratio = detail::SpeedRatios<double>(g, nominal);

  // Parameter modes evaluated once: nominal, all intervals, and one per uncertain parameter.
  const ModeData at_nominal = Evaluate(g, nominal, aiding, w_operating);
  ModeData at_all;
  std::vector<ModeData> singles;
  if (options.intervals) {
    at_all = Evaluate(g, all, aiding, w_operating_all);
    if (options.rank)
      for (const auto& [component, parameter] : detail::UncertainParameters(g))
        singles.push_back(Evaluate(g, {detail::ParameterMode::kOne, component, parameter}, aiding, w_operating, &at_nominal));
  } else {
    at_all = at_nominal;
  }
  const ModeData& bounds = at_all;  // the mode every enclosure below is taken over

  auto scenario_name = [&](const std::string& kind, const std::string& component) {
    for (const Scenario& s : project.scenarios) {
      if (s.kind != kind) continue;
      const auto& target = kind == kJamKind ? s.jam_component : s.rupture_component;
      if (target && *target == component) return s.name;
    }
    return kind + "_" + component;
  };

  // Jams: at every actuator. The whole drive turns at the operating speed; the jammed station is
  // the stop. Static: the drive keeps pushing, up to the PDU stall torque or the STL lock-out.
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const int a = static_cast<int>(i);
    if (!g.IsActuator(a)) continue;
    PeakCase pc;
    pc.kind = kJamKind;
    pc.component = g.Id(a);
    pc.name = scenario_name(kJamKind, pc.component);
    if (!options.only_case.empty() && pc.name != options.only_case) continue;
    const Focus focus{-1, a};
    const FocusModel fm = Reduce(g, focus, elements);
    pc.acts_at = g.Id(a);
    for (int k : g.PathToRoot(a)) pc.load_path.push_back(g.Id(k));
    pc.w_max = w_operating;
    pc.w_max_bounds = w_operating_all.ToDomain();
    pc.J_star = fm.oscillator.J_star;
    pc.c_star = fm.oscillator.c_star;
    pc.omega = fm.oscillator.omega;
    pc.first_mode_share = fm.oscillator.first_mode_share;
    pc.tau_dynamic.nominal = PeakTorque(pc.w_max, fm.oscillator);
    // Static part at nominal values and its enclosure over the domains (every term over its domain).
    // The PDU's stall torque by its law (a hydraulic drive's from its motors, as simulated).
    const detail::ModeReader<double> pdu_nominal(pdu, detail::ParameterMode{});
    const detail::ModeReader<Interval> pdu_bounds(pdu, bounds.mode);
    const bool stall = model::HasPduStallTorque(pdu, pdu_nominal);
    double static_torque = stall ? model::PduStallTorque(pdu, pdu_nominal) : 0.0;
    Interval static_bounds = stall ? model::PduStallTorque(pdu, pdu_bounds) : Interval(0.0);
    pc.tau_static_drive = static_torque;
    pc.tau_static_drive_bounds = static_bounds.ToDomain();
    for (int k : g.PathToRoot(a))
      if (g.Roles(k).wing_limiter) {
        const Component& stl = *g.nodes[k].component;
        static_torque = detail::SystemLimiterPasses(stl, static_torque, speed_ratio[k], nominal);
        static_bounds = detail::SystemLimiterPasses(stl, static_bounds, bounds.n[k], bounds.mode);
      }
    pc.tau_static = static_torque;
    pc.tau_static_bounds = static_bounds.ToDomain();
    pc.note = "static part: PDU stall torque, through the system torque limiter on the path (its end-stop torque, or "
              "the excess over its brake torque); components behind "
              "a station torque limiter see what it does not ground: its end-stop torque, or the excess over its "
              "brake torque";
    Interval omega(pc.omega), J(pc.J_star);
    if (options.intervals) Enclose(g, focus, elements, all, &omega, &J);
    pc.tau_dynamic.bounds = (w_operating_all * omega * J).ToDomain();
    if (options.intervals && options.rank) pc.ranking = Rank(g, focus, fm, pc.w_max, at_nominal, singles, nullptr);
    report.cases.push_back(std::move(pc));
  }

  // Ruptures: at every shaft segment with a wing-tip brake beyond it. The outboard part is
  // back-driven by the airload until the monitor trips and the brake engages; the brake is the stop.
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const int s = static_cast<int>(i);
    if (!g.Has(s, &model::ComponentRoles::segment) || g.nodes[s].children.empty()) continue;
    const int root = g.nodes[s].children.front();
    const std::vector<int> part = g.Subtree(root);
    int brake = -1;
    for (int k : part)
      if (g.Has(k, &model::ComponentRoles::tip_brake)) brake = k;
    // No brake beyond, nothing but the brake, or nothing the brake does not hold rigidly.
    if (brake < 0 || brake == root || !HasFreeInertia(g, {root, brake}, elements)) continue;
    PeakCase pc;
    pc.kind = "rupture";
    pc.component = g.Id(s);
    pc.name = scenario_name("rupture", pc.component);
    if (!options.only_case.empty() && pc.name != options.only_case) continue;
    const Focus focus{root, brake};
    const FocusModel fm = Reduce(g, focus, elements);
    pc.acts_at = g.Id(brake);
    for (int k = brake; k >= 0; k = g.nodes[k].parent) {
      pc.load_path.push_back(g.Id(k));
      if (k == root) break;
    }
    const Component* sensor = FindSensor(g, part);
    const Component& wtb = *g.nodes[brake].component;
    // w_max rises with the back-drive torque, thresholds and latencies, falls with drag and J:
    // its lower and upper corners bound it.
    // The speed ratio, the operating and reference speeds are those of the mode: nominal points
    // for at_nominal and the single-parameter modes, enclosures for at_all.
    auto rupture_speed = [&](const ModeData& d, bool upper) {
      const auto pick = [upper](const Interval& x, bool rising) { return (rising == upper) ? x.hi : x.lo; };
      const bool wide = &d == &at_all && options.intervals;
      Interval J_total(0.0);
      for (int k : part) J_total += d.J[k] + d.link_J[k];
      const Interval n = d.n[root];
      RuptureInput in;
      in.w0 = pick(wide ? w_operating_all : Interval(w_operating), true);
      in.J = pick(J_total, false);
      in.tau_aiding = std::max(0.0, pick(-(d.back->tau_in[root] * n), true));
      in.tau_drag = std::max(0.0, pick(d.drag->tau_in[root] * n, false));
      in.w_reference = pick(wide ? w_reference_all : Interval(w_reference), true);
      in.overspeed_factor = sensor ? pick(detail::Read<Interval>(*sensor, "overspeed_factor", d.mode), true) : 1.3;
      in.asymmetry_threshold =
          sensor ? pick(detail::Read<Interval>(*sensor, "asymmetry_threshold", d.mode), true) : 4.0 * std::numbers::pi;
      const Interval latency = (sensor ? detail::Read<Interval>(*sensor, "latency", d.mode) : Interval(0.0)) +
                               detail::Read<Interval>(wtb, "engagement_latency", d.mode) +
                               Interval(0.5) * detail::Read<Interval>(wtb, "time_to_max_torque", d.mode);
      in.latency = pick(latency, true);
      return std::make_pair(ComputeRuptureSpeed(in), in.tau_aiding);
    };
    const auto [speed, backdrive] = rupture_speed(at_nominal, true);
    pc.w_max = speed.w_max;
    pc.trigger = speed.trigger;
    pc.tau_static = backdrive;
    pc.tau_static_bounds = {rupture_speed(bounds, false).second, rupture_speed(bounds, true).second};
    pc.J_star = fm.oscillator.J_star;
    pc.c_star = fm.oscillator.c_star;
    pc.omega = fm.oscillator.omega;
    pc.first_mode_share = fm.oscillator.first_mode_share;
    pc.tau_dynamic.nominal = PeakTorque(pc.w_max, fm.oscillator);
    pc.note = "static part: airload back-drive torque through the aiding efficiencies, friction neglected; the brake "
              "stops the part as a rigid stop until the shaft torque reaches what it can pass, where it slips; "
              "capped there, tau_max is an estimate, not a bound: the shaft next to the brake also carries the "
              "inertia torque of the rotor and shaft between it and the friction face (the transient exceeds the "
              "cap; docs/reduced_models.md, peak --transient)";
    if (const model::ComponentModel* m = detail::ModelOf(wtb)) {
      const auto nominal_limit = m->StopTorqueLimit(detail::ModeReader<double>(wtb, nominal));
      const auto limit_bounds = m->StopTorqueLimit(detail::ModeReader<Interval>(wtb, bounds.mode));
      if (nominal_limit && limit_bounds) pc.stop_limit = Bounded{*nominal_limit, limit_bounds->ToDomain()};
    }
    Interval omega(pc.omega), J(pc.J_star), w(pc.w_max);
    if (options.intervals) {
      Enclose(g, focus, elements, all, &omega, &J);
      w = Interval(rupture_speed(at_all, false).first.w_max, rupture_speed(at_all, true).first.w_max);
    }
    pc.w_max_bounds = w.ToDomain();
    pc.tau_dynamic.bounds = (w * omega * J).ToDomain();
    // The back-driven flaps: each actuator beyond the break turns at its station's share of the
    // rupture speed when the brake stops the shaft; its station limiter, at its end stop with its
    // brake grounding the input, is the stiffest path to ground (c3 > c1 > c2), so the flap's
    // kinetic energy 1/2 J_a w_a^2 stored in it gives at most w_a sqrt(c3 J_a) (equation (1) on the
    // flap's own oscillator), plus the flap's back-drive torque. An estimate: it neglects the energy
    // the shaft side can feed into the station (docs/reduced_models.md, "Actuators in a rupture").
    for (int a : part) {
      const int lim = g.nodes[a].parent;
      if (!g.IsActuator(a) || lim < 0 || !g.Roles(lim).station_limiter) continue;
      const Component& limiter = *g.nodes[lim].component;
      if (!detail::HasValue(limiter, "stiffness_end_stop")) continue;
      PeakCase::FlapLoad f;
      f.actuator = g.Id(a);
      f.limiter = g.Id(lim);
      const double c3 = detail::NominalValue(limiter, "stiffness_end_stop") * speed_ratio[lim] * speed_ratio[lim];
      const double back = std::max(0.0, (-(at_nominal.back->tau_in[a] * at_nominal.n[a])).hi);
      f.torque.nominal = detail::PeakTorque(pc.w_max, c3, at_nominal.J[a].hi) + back;
      const Interval c3_all = detail::Read<Interval>(limiter, "stiffness_end_stop", bounds.mode) * bounds.n[lim] * bounds.n[lim];
      const Interval back_all = -(bounds.back->tau_in[a] * bounds.n[a]);
      const Interval back_pos(std::max(0.0, back_all.lo), std::max(0.0, back_all.hi));
      f.torque.bounds = (detail::PeakTorque(w, c3_all, bounds.J[a]) + back_pos).ToDomain();
      pc.flap_loads.push_back(std::move(f));
    }
    if (options.intervals && options.rank)
      pc.ranking = Rank(g, focus, fm, pc.w_max, at_nominal, singles, [&](const ModeData& one) {
        return rupture_speed(one, true).first.w_max - rupture_speed(one, false).first.w_max;
      });
    report.cases.push_back(std::move(pc));
  }

  if (!options.only_case.empty() && report.cases.empty()) {
    std::string names;
    PeakOptions all_cases = options;
    all_cases.only_case.clear();
    all_cases.intervals = false;
    all_cases.rank = false;
    for (const auto& c : AnalysePeaks(project, all_cases).cases) names += (names.empty() ? "" : ", ") + c.name;
    throw InputError("peak case '" + options.only_case + "' does not exist; the cases are: " + names);
  }

  for (auto& pc : report.cases) {
    pc.tau_total.nominal = pc.tau_dynamic.nominal + pc.tau_static;
    Interval total = Interval::FromDomain(pc.tau_dynamic.bounds) + Interval::FromDomain(pc.tau_static_bounds);
    if (pc.stop_limit) {  // the stop slips: the shaft at it carries no more than it passes
      pc.tau_total.nominal = std::min(pc.tau_total.nominal, pc.stop_limit->nominal);
      total = detail::Min(total, Interval::FromDomain(pc.stop_limit->bounds));
    }
    pc.tau_total.bounds = total.ToDomain();
  }

  // Worst case per component on any load path, with its allowable. In a jam, a station torque
  // limiter grounds into its housing what its brake holds: what lies behind it sees the torque
  // its type's law passes on (ComponentModel::JamPassedTorque: at most the end-stop torque while
  // the brake grounds the excess, the excess over the brake torque beyond). The torque passed
  // (nominal and its enclosure) and everything after it are taken over the same domains as the
  // case's enclosure, so the margin below is guaranteed: the smallest allowable against the
  // largest local torque.
  std::map<std::string, ComponentPeak> worst;
  for (const auto& pc : report.cases) {
    for (const auto& f : pc.flap_loads)
      for (const std::string& id : {f.limiter, f.actuator}) {
        auto& w = worst[id];
        if (w.component.empty() || f.torque.bounds.hi > w.torque.bounds.hi) {
          w.component = id;
          w.worst_case = pc.name;
          w.torque = f.torque;
        }
        if (f.torque.bounds.lo > w.torque_certain) {
          w.torque_certain = f.torque.bounds.lo;
          w.certain_case = pc.name;
        }
      }
    Bounded through = pc.tau_total;  // N*m at the reference speed: what reaches the component
    // A jam: the PDU and what lies before the system torque limiter carry the whole stall torque,
    // not the share the limiter passes on.
    const bool has_drive_side = pc.kind == kJamKind && pc.tau_static_drive_bounds.bounded();
    bool drive_side = has_drive_side;
    Bounded drive_through;
    if (has_drive_side) {
      drive_through.nominal = pc.tau_dynamic.nominal + pc.tau_static_drive;
      drive_through.bounds = (Interval::FromDomain(pc.tau_dynamic.bounds) +
                              Interval::FromDomain(pc.tau_static_drive_bounds)).ToDomain();
    }
    for (auto id = pc.load_path.rbegin(); id != pc.load_path.rend(); ++id) {
      const int k = g.Find(*id);
      auto& w = worst[*id];
      const Bounded path_through = through;
      if (drive_side) through = drive_through;
      if (w.component.empty() || through.bounds.hi > w.torque.bounds.hi) {
        w.component = *id;
        w.worst_case = pc.name;
        w.torque = through;
      }
      if (through.bounds.lo > w.torque_certain) {
        w.torque_certain = through.bounds.lo;
        w.certain_case = pc.name;
      }
      through = path_through;
      if (g.Roles(k).wing_limiter) drive_side = false;  // beyond it: what it passes on
      // A limiter in a down-drive (LimitedPort) limits only when the path goes on through that port.
      const int limited = g.LimitedNode(k);
      const bool behind = limited == k || (std::next(id) != pc.load_path.rend() && g.Find(*std::next(id)) == limited);
      const model::ComponentModel* m = detail::ModelOf(*g.nodes[k].component);
      if (pc.kind == kJamKind && behind && g.Roles(k).station_limiter && m) {
        const Component& limiter = *g.nodes[k].component;
        const auto nominal_pass = m->JamPassedTorque(detail::ModeReader<double>(limiter, nominal), through.nominal,
                                                     speed_ratio[limited]);
        const auto pass_bounds = m->JamPassedTorque(detail::ModeReader<Interval>(limiter, bounds.mode),
                                                    Interval::FromDomain(through.bounds), bounds.n[limited]);
        if (nominal_pass && pass_bounds) {
          through.nominal = *nominal_pass;
          through.bounds = pass_bounds->ToDomain();
        }
      }
    }
  }
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    auto it = worst.find(g.Id(static_cast<int>(i)));
    if (it == worst.end()) continue;
    ComponentPeak& w = it->second;
    const Component& c = *g.nodes[i].component;
    // Largest torque at the component's own speed: the largest reference torque over the smallest ratio.
    w.local_torque = (Interval(w.torque.bounds.hi) / bounds.n[i]).hi;
    w.local_nominal = w.torque.nominal / speed_ratio[i];
    // The allowable at its input flange, by its type's law: nominal and over the domains.
    std::optional<Interval> allowable;
    if (const model::ComponentModel* m = detail::ModelOf(c)) {
      if (const auto a = m->PeakAllowable(detail::ModeReader<double>(c, nominal))) {
        w.allowable_name = a->name;
        w.allowable = a->value;
        allowable = m->PeakAllowable(detail::ModeReader<Interval>(c, bounds.mode))->value;
      }
    }
    w.allowable_min = allowable ? allowable->lo : 0.0;
    // Guaranteed: no point of the domains has a smaller margin (outward rounded).
    w.margin = w.allowable_min > 0.0 ? GuaranteedMargin(w.allowable_min, w.local_torque) : kInf;
    // Certain: no point of the domains has a larger margin (the least load of the case that loads
    // it most surely over the largest ratio, against the largest allowable; outward rounded).
    w.local_torque_certain = w.torque_certain > 0.0 ? (Interval(w.torque_certain) / bounds.n[i]).lo : 0.0;
    w.allowable_max = allowable ? allowable->hi : 0.0;
    w.margin_max = allowable && w.local_torque_certain > 0.0 && std::isfinite(w.allowable_max)
                       ? std::nextafter(std::nextafter(w.allowable_max / w.local_torque_certain, kInf) - 1.0, kInf)
                       : kInf;
    report.worst.push_back(w);
  }
  if (options.intervals && options.tightness_samples > 0) MeasureTightness(project, options, &report);
  return report;
}

void MeasureTightness(const Project& project, const PeakOptions& options, PeakReport* report) {
  const std::vector<UncertainParameter> uncertain = UncertainParameters(project);
  const std::size_t cases = report->cases.size(), worst = report->worst.size();
  SampledHull dynamic(cases), total(cases), component(worst);
  DomainSampler sampler(uncertain, options.tightness_seed);
  PeakOptions point_options = options;
  point_options.intervals = false;
  point_options.rank = false;
  point_options.tightness_samples = 0;
  const int samples = uncertain.empty() ? 1 : options.tightness_samples;
  for (int k = 0; k < samples; ++k) {
    const PeakReport at = AnalysePeaks(FixParameters(project, uncertain, sampler.Next()), point_options);
    HIGHLIFT_CHECK(at.cases.size() == cases && at.worst.size() == worst, "peak cases differ between the enclosure and a point");
    for (std::size_t i = 0; i < cases; ++i) {
      HIGHLIFT_CHECK(at.cases[i].name == report->cases[i].name, "peak cases differ between the enclosure and a point");
      dynamic.Add(i, at.cases[i].tau_dynamic.nominal);
      total.Add(i, at.cases[i].tau_total.nominal);
    }
    for (std::size_t i = 0; i < worst; ++i) component.Add(i, at.worst[i].torque.nominal);
  }
  for (std::size_t i = 0; i < cases; ++i) {
    report->cases[i].tau_dynamic.SetTightness(dynamic.lo[i], dynamic.hi[i]);
    report->cases[i].tau_total.SetTightness(total.lo[i], total.hi[i]);
  }
  for (std::size_t i = 0; i < worst; ++i) report->worst[i].torque.SetTightness(component.lo[i], component.hi[i]);
}

bool PeakReport::ok() const {
  for (const auto& w : worst)
    if (w.margin < 0.0) return false;
  return true;
}

std::string PeakReport::BriefReport() const {
  const PeakCase* top = nullptr;
  for (const auto& c : cases)
    if (!top || c.tau_total.bounds.hi > top->tau_total.bounds.hi) top = &c;
  std::string out = "peak loads of '" + project + "': " + std::to_string(cases.size()) + " case(s)";
  if (top) out += "; worst " + top->name + ": " + Fmt(top->tau_total.nominal) + " N*m at " + top->acts_at;
  int negative = 0;
  for (const auto& w : worst) negative += w.margin < 0.0 ? 1 : 0;
  out += negative ? "; " + std::to_string(negative) + " negative margin(s)" : "; all margins >= 0";
  return out;
}

std::string PeakReport::FullReport() const {
  std::string out = "Single-DOF peak loads (paper eq. 1): " + project + " (" + reduction + ")\n";
  TextTable table({"case", "acts at", "w_max [rad/s]", "J* [kg*m^2]", "c* [N*m/rad]", "f1 [Hz]", "mode-1 share",
                   "tau_dyn [N*m]", "enclosure [N*m]", "tau_static [N*m]", "stop slips at [N*m]", "tau_max [N*m]",
                   "enclosure [N*m]", "widest parameter"},
                  {2, 3, 4, 5, 6, 7, 9, 10, 11});
  for (const auto& c : cases)
    table.AddRow({c.name, c.acts_at, Fmt(c.w_max), Fmt(c.J_star), Fmt(c.c_star), Fmt(Hz(c.omega)), Fmt(c.first_mode_share, 3),
                  Fmt(c.tau_dynamic.nominal), "[" + Fmt(c.tau_dynamic.bounds.lo) + ", " + Fmt(c.tau_dynamic.bounds.hi) + "]",
                  Fmt(c.tau_static), c.stop_limit ? Fmt(c.stop_limit->nominal) : "-", Fmt(c.tau_total.nominal),
                  "[" + Fmt(c.tau_total.bounds.lo) + ", " + Fmt(c.tau_total.bounds.hi) + "]",
                  c.ranking.empty() ? "-" : c.ranking[0].parameter + " (" + Fmt(100 * c.ranking[0].share, 3) + " %)"});
  out += table.ToString();
  // A rupture's tau_max capped at the wing-tip brake's slipping torque is an estimate (the
  // rupture block of AnalysePeaks): say so wherever it is printed.
  const auto capped = [](const PeakCase& c) { return c.stop_limit && c.tau_total.nominal >= c.stop_limit->nominal; };
  std::set<std::string> capped_cases;
  for (const auto& c : cases)
    if (capped(c)) capped_cases.insert(c.name);
  if (!capped_cases.empty())
    out += "ESTIMATE, not a bound: tau_max of " + std::to_string(capped_cases.size()) +
           " rupture case(s) is capped where the wing-tip brake slips; the shaft next to the brake also carries the "
           "inertia torque between it and the friction face, and the transient exceeds the cap (peak --transient "
           "says by how much)\n";
  out += "\nWorst case per component (margin: the smallest allowable over the domains against the largest local "
         "torque; no point of the domains has a smaller margin, except where the worst case is a capped rupture "
         "estimate)\n";
  bool flaps = false;
  for (const auto& c : cases) flaps = flaps || !c.flap_loads.empty();
  if (flaps)
    out += "(an actuator or station limiter whose worst case is a rupture: its back-driven flap stopped on the "
           "limiter's end stop, w sqrt(c3 J) + back-drive torque, an estimate; docs/reduced_models.md)\n";
  TextTable worst_table({"component", "worst case", "tau_max [N*m]", "upper bound [N*m]", "local torque [N*m]", "allowable",
                         "allowable min [N*m]", "margin"},
                        {2, 3, 4, 6, 7});
  for (const auto& w : worst)
    worst_table.AddRow({w.component, w.worst_case, Fmt(w.torque.nominal), Fmt(w.torque.bounds.hi), Fmt(w.local_torque),
                        w.allowable_name.empty() ? "-" : w.allowable_name, w.allowable_min > 0 ? Fmt(w.allowable_min) : "-",
                        std::isinf(w.margin) ? "-" : Fmt(100.0 * w.margin, 3) + " %"});
  return out + worst_table.ToString();
}

nlohmann::json PeakReport::ToJson() const {
  auto bounded = [](const Bounded& b) { return reduced_models::ToJson(b); };
  nlohmann::json j = {{"project", project}, {"model", reduction}, {"ok", ok()}};
  j["cases"] = nlohmann::json::array();
  for (const auto& c : cases) {
    nlohmann::json ranking = nlohmann::json::array();
    for (const auto& r : c.ranking) ranking.push_back({{"parameter", r.parameter}, {"width_N_m", r.width}, {"share", r.share}});
    j["cases"].push_back({{"name", c.name}, {"kind", c.kind}, {"component", c.component}, {"acts_at", c.acts_at},
                          {"load_path", c.load_path}, {"w_max_rad_s", c.w_max},
                          {"w_max_bounds", {c.w_max_bounds.lo, c.w_max_bounds.hi}}, {"trigger", c.trigger},
                          {"J_star_kg_m2", c.J_star}, {"c_star_N_m_rad", c.c_star}, {"omega_rad_s", c.omega},
                          {"first_mode_share", c.first_mode_share}, {"tau_dynamic_N_m", bounded(c.tau_dynamic)},
                          {"tau_static_N_m", c.tau_static},
                          {"tau_static_bounds_N_m", {c.tau_static_bounds.lo, c.tau_static_bounds.hi}},
                          {"stop_limit_N_m", c.stop_limit ? bounded(*c.stop_limit) : nlohmann::json(nullptr)},
                          {"tau_max_N_m", bounded(c.tau_total)},
                          // capped at the wing-tip brake's slipping torque: an estimate, not a bound
                          {"tau_max_is_estimate", c.stop_limit.has_value() && c.tau_total.nominal >= c.stop_limit->nominal},
                          {"ranking", ranking},
                          {"note", c.note}});
    if (c.kind != "jam") {
      nlohmann::json flaps = nlohmann::json::array();
      for (const auto& f : c.flap_loads)
        flaps.push_back({{"actuator", f.actuator}, {"limiter", f.limiter}, {"tau_N_m", bounded(f.torque)}});
      j["cases"].back()["flap_loads"] = flaps;
    }
  }
  j["worst"] = nlohmann::json::array();
  for (const auto& w : worst)
    j["worst"].push_back({{"component", w.component}, {"worst_case", w.worst_case}, {"tau_max_N_m", bounded(w.torque)},
                          {"local_torque_N_m", w.local_torque}, {"local_nominal_N_m", w.local_nominal},
                          {"allowable_name", w.allowable_name},
                          {"allowable_N_m", w.allowable > 0 ? nlohmann::json(w.allowable) : nlohmann::json(nullptr)},
                          {"allowable_min_N_m", w.allowable_min > 0 ? nlohmann::json(w.allowable_min) : nlohmann::json(nullptr)},
                          {"margin", std::isfinite(w.margin) ? nlohmann::json(w.margin) : nlohmann::json(nullptr)},
                          // < 0: the margin fails at every point of the domains (in certain_case)
                          {"margin_max", std::isfinite(w.margin_max) ? nlohmann::json(w.margin_max) : nlohmann::json(nullptr)},
                          {"certain_case", w.certain_case}});
  return j;
}

}  // namespace highlift::reduced_models

// ---------------------------------------------------------------------------------------------
// The structure of the sizing cases, for constraint solvers (additive: AnalysePeaks is unchanged;
// the case selection below repeats its rules and a test in tests/icsp compares both per case).

namespace highlift::reduced_models {

double ReducedModelValue(const Component& component, std::string_view name) {
  return detail::NominalValue(component, name);
}
bool HasReducedModelValue(const Component& component, std::string_view name) {
  return detail::HasValue(component, name);
}

PeakStructure DescribePeaks(const Project& project, const PeakOptions& options) {
  const detail::Graph g = detail::BuildGraph(project);
  const Component& pdu = *g.nodes[0].component;
  const detail::ParameterMode nominal;
  PeakStructure out;
  out.elements_per_segment = std::max(1, options.elements_per_segment);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const detail::GraphNode& n = g.nodes[i];
    PeakGraphNode node{n.component->id, n.component->type, n.parent, "", n.children};
    if (n.parent >= 0) {
      // A gear stage between the parent's entry and this node's port (its speed law has a ratio).
      const detail::GraphNode& up = g.nodes[n.parent];
      const model::ComponentModel* m = detail::ModelOf(*up.component);
      if (m && !m->SpeedRatioLaw(up.entry_port, n.parent_port).parameter.empty()) node.gear = up.component->id;
    }
    out.nodes.push_back(std::move(node));
  }
  if (project.load_cases.empty())
    throw InputError("project '" + project.name + "' has no load cases; the peak loads need the operating speed and "
                     "the airloads: add a load case under \"load_cases\"");
  for (const LoadCase& lc : project.load_cases) {
    out.w_operating = std::max(out.w_operating, detail::SizingSpeed(lc, pdu));
    for (const auto& [actuator, value] : detail::SizingLoads(lc))
      out.aiding[actuator] = std::min(out.aiding[actuator], -std::abs(value));
  }
  out.w_reference = detail::HasValue(pdu, "max_output_speed") ? detail::NominalValue(pdu, "max_output_speed") : out.w_operating;
  auto scenario_name = [&](const std::string& kind, const std::string& component) {
    for (const Scenario& s : project.scenarios) {
      if (s.kind != kind) continue;
      const auto& target = kind == kJamKind ? s.jam_component : s.rupture_component;
      if (target && *target == component) return s.name;
    }
    return kind + "_" + component;
  };
  auto fill = [&](PeakCaseStructure& pc, int root, int stop) {
    const auto draft = detail::BuildTransmission<double>(g, nominal, root);
    pc.root = root;
    pc.transmission = Nominal(draft);
    pc.point_of_node = draft.point_of_node;
    pc.link_of_node = draft.link_of_node;
    pc.stop_point = draft.point_of_node[stop];
    if (root < 0) {
      for (std::size_t i = 0; i < g.nodes.size(); ++i) pc.part.push_back(static_cast<int>(i));
    } else {
      pc.part = g.Subtree(root);
    }
  };
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const int a = static_cast<int>(i);
    if (!g.IsActuator(a)) continue;
    PeakCaseStructure pc;
    pc.kind = kJamKind;
    pc.component = g.Id(a);
    pc.name = scenario_name(kJamKind, pc.component);
    pc.acts_at = g.Id(a);
    for (int k : g.PathToRoot(a)) pc.load_path.push_back(g.Id(k));
    fill(pc, -1, a);
    out.cases.push_back(std::move(pc));
  }
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const int s = static_cast<int>(i);
    if (!g.Has(s, &model::ComponentRoles::segment) || g.nodes[s].children.empty()) continue;
    const int root = g.nodes[s].children.front();
    const std::vector<int> part = g.Subtree(root);
    int brake = -1;
    for (int k : part)
      if (g.Has(k, &model::ComponentRoles::tip_brake)) brake = k;
    if (brake < 0 || brake == root) continue;
    PeakCaseStructure pc;
    pc.kind = "rupture";
    pc.component = g.Id(s);
    pc.name = scenario_name("rupture", pc.component);
    pc.acts_at = g.Id(brake);
    for (int k = brake; k >= 0; k = g.nodes[k].parent) {
      pc.load_path.push_back(g.Id(k));
      if (k == root) break;
    }
    fill(pc, root, brake);
    if (const Component* sensor = FindSensor(g, part)) pc.sensor = sensor->id;
    pc.brake = g.Id(brake);
    out.cases.push_back(std::move(pc));
  }
  return out;
}

}  // namespace highlift::reduced_models
