#include "soundness/soundness.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "highlift/core/error.h"
#include "highlift/icsp/drive_system.h"
#include "highlift/icsp/propagator.h"
#include "highlift/reduced_models/analyses.h"
#include "highlift/reduced_models/sampling.h"
#include "highlift/reduced_models/sizing.h"

namespace highlift::testing {
namespace {

using reduced_models::Bounded;
using reduced_models::DomainSampler;
using reduced_models::FixParameters;
using reduced_models::UncertainParameter;

std::string Number(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

/// Collects containment checks of one point against the enclosures of one project.
class Checker {
 public:
  Checker(const Project& project, const SoundnessOptions& options, SoundnessResult* result)
      : project_(project), options_(options), result_(result) {}

  void SetPoint(int index, const std::vector<UncertainParameter>& uncertain, const std::vector<double>& x) {
    point_ = index;
    where_.clear();
    for (std::size_t i = 0; i < x.size() && i < 6; ++i)
      where_ += (i ? ", " : "") + uncertain[i].component + "." + uncertain[i].parameter + "=" + Number(x[i]);
    if (x.size() > 6) where_ += ", ... (" + std::to_string(x.size()) + " parameters)";
  }

  double Slack(double a, double b, double c) const {
    return options_.relative_slack * std::max({std::abs(a), std::abs(b), std::abs(c), 1e-300});
  }

  /// value in [lo, hi] (with the slack).
  void Inside(const std::string& what, double value, double lo, double hi) {
    ++result_->checks;
    const double slack = Slack(value, lo, hi);
    if (!(value >= lo - slack && value <= hi + slack)) Fail(what, value, "[" + Number(lo) + ", " + Number(hi) + "]");
  }
  void Inside(const std::string& what, double value, const Domain& d) { Inside(what, value, d.lo, d.hi); }
  void Inside(const std::string& what, const Bounded& point, const Bounded& enclosure) {
    Inside(what, point.nominal, enclosure.bounds);
  }
  /// A guaranteed lower bound: value >= bound.
  void AtLeast(const std::string& what, double value, double bound) {
    ++result_->checks;
    if (std::isinf(bound) && std::isinf(value)) return;
    if (!(value >= bound - Slack(value, bound, 0.0))) Fail(what, value, ">= " + Number(bound));
  }
  /// A guaranteed upper bound: value <= bound.
  void AtMost(const std::string& what, double value, double bound) {
    ++result_->checks;
    if (!(value <= bound + Slack(value, bound, 0.0))) Fail(what, value, "<= " + Number(bound));
  }
  /// Two enclosures of one quantity meet.
  void Meet(const std::string& what, double lo_a, double hi_a, double lo_b, double hi_b) {
    ++result_->checks;
    const double slack = Slack(lo_a, hi_a, std::max(std::abs(lo_b), std::abs(hi_b)));
    if (hi_a < lo_b - slack || hi_b < lo_a - slack)
      Fail(what, lo_a, "point enclosure [" + Number(lo_a) + ", " + Number(hi_a) + "] misses [" + Number(lo_b) + ", " +
                           Number(hi_b) + "]");
  }

 private:
  void Fail(const std::string& what, double value, const std::string& enclosure) {
    result_->violations.push_back("project '" + project_.name + "', seed " + std::to_string(options_.seed) + ", point " +
                                  std::to_string(point_) + " (" + where_ + "): " + what + " = " + Number(value) +
                                  " not in " + enclosure);
  }
  const Project& project_;
  const SoundnessOptions& options_;
  SoundnessResult* result_;
  int point_ = -1;
  std::string where_;
};

void CompareSizing(const reduced_models::SizingReport& wide, const reduced_models::SizingReport& at, Checker& check) {
  if (wide.cases.size() != at.cases.size()) {
    check.Inside("number of load cases", static_cast<double>(at.cases.size()), static_cast<double>(wide.cases.size()),
                 static_cast<double>(wide.cases.size()));
    return;
  }
  for (std::size_t i = 0; i < wide.cases.size(); ++i) {
    const auto &w = wide.cases[i], &p = at.cases[i];
    const std::string lc = "size " + w.load_case + ": ";
    check.Inside(lc + "PDU torque", p.pdu_torque, w.pdu_torque);
    check.Inside(lc + "PDU power", p.pdu_power, w.pdu_power);
    check.Inside(lc + "PDU input power", p.pdu_input_power, w.pdu_input_power);
    for (std::size_t k = 0; k < w.components.size() && k < p.components.size(); ++k)
      check.Inside(lc + w.components[k].component + " torque", p.components[k].torque, w.components[k].torque);
  }
  for (std::size_t i = 0; i < wide.settings.size() && i < at.settings.size(); ++i)
    check.Inside("size setting " + wide.settings[i].component + "." + wide.settings[i].parameter + " operating torque",
                 at.settings[i].operating, wide.settings[i].operating);
  for (std::size_t i = 0; i < wide.margins.size() && i < at.margins.size(); ++i) {
    const std::string what = "size margin " + wide.margins[i].component + " (" + wide.margins[i].allowable_name + ")";
    check.AtLeast(what, at.margins[i].margin, wide.margins[i].margin);
    check.AtLeast(what + " allowable", at.margins[i].allowable, wide.margins[i].allowable);
    check.AtMost(what + " load", at.margins[i].load, wide.margins[i].load);
  }
}

void ComparePeaks(const reduced_models::PeakReport& wide, const reduced_models::PeakReport& at, Checker& check) {
  std::map<std::string, const reduced_models::PeakCase*> cases;
  for (const auto& c : at.cases) cases[c.name] = &c;
  for (const auto& w : wide.cases) {
    auto it = cases.find(w.name);
    if (it == cases.end()) continue;
    const auto& p = *it->second;
    const std::string pc = "peak " + w.name + ": ";
    check.Inside(pc + "w_max", p.w_max, w.w_max_bounds);
    check.Inside(pc + "tau_dynamic", p.tau_dynamic, w.tau_dynamic);
    check.Inside(pc + "tau_static", p.tau_static, w.tau_static_bounds);
    check.Inside(pc + "tau_total", p.tau_total, w.tau_total);
  }
  std::map<std::string, const reduced_models::ComponentPeak*> worst;
  for (const auto& c : at.worst) worst[c.component] = &c;
  for (const auto& w : wide.worst) {
    auto it = worst.find(w.component);
    if (it == worst.end()) continue;
    const auto& p = *it->second;
    check.AtMost("peak worst " + w.component + " torque", p.torque.nominal, w.torque.bounds.hi);
    check.AtMost("peak worst " + w.component + " local torque", p.local_torque, w.local_torque);
    check.AtLeast("peak worst " + w.component + " margin", p.margin, w.margin);
  }
}

/// The parameters the propagator treats as uncertain: a parameter the project does not give is
/// a point at its catalogue nominal there (the reduced models take its default domain), so the
/// points are drawn from the initial domains of the network's own variables.
std::vector<UncertainParameter> PropagatorUncertainParameters(const Project& project,
                                                              const icsp::DriveSystemNetwork& network) {
  std::vector<UncertainParameter> uncertain;
  for (UncertainParameter u : reduced_models::UncertainParameters(project)) {
    const icsp::VariableId v = network.network.FindVariable(u.component + "." + u.parameter);
    if (v.value < 0) continue;
    const icsp::Interval initial = network.network.variable(v).initial;
    if (!(initial.lower() < initial.upper()) || !std::isfinite(initial.lower()) || !std::isfinite(initial.upper())) continue;
    u.domain = {initial.lower(), initial.upper()};
    uncertain.push_back(u);
  }
  return uncertain;
}

}  // namespace

void SoundnessResult::Merge(const SoundnessResult& other) {
  points += other.points;
  checks += other.checks;
  violations.insert(violations.end(), other.violations.begin(), other.violations.end());
}

SoundnessResult CheckEnclosures(const Project& project, const SoundnessOptions& options) {
  SoundnessResult result;
  Checker check(project, options, &result);
  reduced_models::SizingOptions wide_size;
  reduced_models::PeakOptions wide_peak;
  wide_peak.rank = false;
  reduced_models::SizingOptions point_size = wide_size;
  point_size.intervals = false;
  reduced_models::PeakOptions point_peak = wide_peak;
  point_peak.intervals = false;
  const auto size = options.size ? reduced_models::Size(project, wide_size) : reduced_models::SizingReport{};
  const auto peak = options.peak ? reduced_models::AnalysePeaks(project, wide_peak) : reduced_models::PeakReport{};
  const std::vector<UncertainParameter> uncertain = reduced_models::UncertainParameters(project);
  DomainSampler sampler(uncertain, options.seed);
  for (int k = 0; k < options.points; ++k) {
    const std::vector<double> x = sampler.Next();
    check.SetPoint(k, uncertain, x);
    const Project point = FixParameters(project, uncertain, x);
    if (options.size) CompareSizing(size, reduced_models::Size(point, point_size), check);
    if (options.peak) ComparePeaks(peak, reduced_models::AnalysePeaks(point, point_peak), check);
    ++result.points;
  }
  return result;
}

SoundnessResult CheckDomainSoundness(const Project& project, const SoundnessOptions& options) {
  SoundnessResult result;
  Checker check(project, options, &result);
  const icsp::DriveSystemNetwork network = icsp::BuildDriveSystemNetwork(project);
  const icsp::CheckResult wide = icsp::CheckDriveSystem(network);
  std::map<std::string, const icsp::ParameterResult*> narrowed;
  for (const auto& p : wide.parameters) narrowed[p.name] = &p;
  const std::vector<UncertainParameter> uncertain = PropagatorUncertainParameters(project, network);
  DomainSampler sampler(uncertain, options.seed);
  for (int k = 0; k < options.points; ++k) {
    const std::vector<double> x = sampler.Next();
    check.SetPoint(k, uncertain, x);
    const icsp::CheckResult at = icsp::CheckDriveSystem(icsp::BuildDriveSystemNetwork(FixParameters(project, uncertain, x)));
    ++result.points;
    if (!at.feasible) continue;  // the property speaks of feasible points only
    if (!wide.feasible) {
      check.Inside("check: the project was proved infeasible, yet this point is feasible", 1.0, 0.0, 0.0);
      continue;
    }
    for (const auto& p : at.parameters) {
      auto it = narrowed.find(p.name);
      if (it == narrowed.end()) continue;
      const icsp::ParameterResult& w = *it->second;
      check.Meet("check domain of " + p.name, p.final.lower(), p.final.upper(), w.final.lower(), w.final.upper());
    }
  }
  return result;
}

SoundnessResult CheckTradeoffSoundness(const Project& project, const std::string& parameter, int slices,
                                       const SoundnessOptions& options) {
  SoundnessResult result;
  Checker check(project, options, &result);
  const icsp::DriveSystemNetwork network = icsp::BuildDriveSystemNetwork(project);
  const icsp::Network& net = network.network;
  const icsp::VariableId varied = net.FindVariable(parameter);
  if (varied.value < 0) throw InputError("tradeoff soundness: no variable '" + parameter + "'");
  const icsp::Interval domain = net.variable(varied).initial;
  // Every uncertain parameter is drawn (so a feasible point is a solution, not a box that was
  // merely not proved empty); the varied one within the slice.
  const std::vector<UncertainParameter> uncertain = PropagatorUncertainParameters(project, network);
  std::size_t index = uncertain.size();
  for (std::size_t i = 0; i < uncertain.size(); ++i)
    if (uncertain[i].component + "." + uncertain[i].parameter == parameter) index = i;
  if (index == uncertain.size()) throw InputError("tradeoff soundness: '" + parameter + "' is not uncertain");
  DomainSampler sampler(uncertain, options.seed);
  icsp::Propagator propagator(net, {});
  std::mt19937_64 random(options.seed);
  for (int k = 0; k < slices; ++k) {
    const double a = domain.lower() + (domain.upper() - domain.lower()) * k / slices;
    const double b = domain.lower() + (domain.upper() - domain.lower()) * (k + 1) / slices;
    icsp::Box box = net.InitialBox();
    box[varied.value] = icsp::Meet(box[varied.value], icsp::Interval(a, b));
    const icsp::Status status = propagator.Propagate(box).status;
    for (int p = 0; p < options.points; ++p) {
      std::vector<double> x = sampler.Interior();
      x[index] = std::min(b, a + (b - a) * (static_cast<double>(random() >> 11) * 0x1.0p-53));
      check.SetPoint(k * options.points + p, uncertain, x);
      const icsp::DriveSystemNetwork at_network = icsp::BuildDriveSystemNetwork(FixParameters(project, uncertain, x));
      const icsp::CheckResult at = icsp::CheckDriveSystem(at_network);
      ++result.points;
      if (!at.feasible) continue;
      if (status == icsp::Status::kInfeasible) {
        check.Inside("tradeoff slice [" + Number(a) + ", " + Number(b) + "] proved infeasible, yet this point is feasible",
                     1.0, 0.0, 0.0);
        continue;
      }
      // Compare the propagated point box with the slice's box, variable by variable (SI).
      icsp::Box point_box = at_network.network.InitialBox();
      icsp::Propagate(at_network.network, point_box);
      for (int v = 0; v < net.num_variables(); ++v) {
        const icsp::VariableId w = at_network.network.FindVariable(net.variable(icsp::VariableId{v}).name);
        if (w.value < 0) continue;
        check.Meet("tradeoff slice " + std::to_string(k) + " domain of " + net.variable(icsp::VariableId{v}).name,
                   point_box[w.value].lower(), point_box[w.value].upper(), box[v].lower(), box[v].upper());
      }
    }
  }
  return result;
}

Project RandomChainProject(std::uint64_t seed, const RandomProjectOptions& options) {
  std::mt19937_64 random(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(random() >> 11) * 0x1.0p-53); };
  auto coin = [&](double p) { return uniform(0.0, 1.0) < p; };
  auto value = [](double v) {
    Parameter p;
    p.nominal = v;
    p.domain = Domain::Point(v);
    p.provenance = Provenance::kUser;
    return p;
  };
  // A nominal value with, half of the time, a domain of relative half-width up to `spread`.
  auto uncertain = [&](double v, double spread) {
    Parameter p = value(v);
    if (coin(0.5)) {
      const double lo = v * (1.0 - uniform(0.0, spread)), hi = v * (1.0 + uniform(0.0, spread));
      p.domain = {std::min(lo, hi), std::max(lo, hi)};
    }
    return p;
  };
  auto efficiency = [&](double lo, double hi) {
    Parameter p = value(uniform(lo, hi));
    if (coin(0.5)) p.domain = {std::min(lo, *p.nominal), std::max(hi, *p.nominal)};
    return p;
  };

  Project p;
  p.name = "random chain " + std::to_string(seed);
  auto add = [&](const std::string& id, const std::string& type, std::map<std::string, Parameter> parameters = {}) {
    Component c;
    c.id = id;
    c.type = type;
    c.parameters = std::move(parameters);
    p.components.push_back(std::move(c));
  };
  auto connect = [&](const std::string& a, const std::string& a_port, const std::string& b, const std::string& b_port) {
    p.connections.push_back({{a, a_port}, {b, b_port}, {}});
  };
  const double w_max = uniform(15.0, 35.0);
  const double stall = uniform(300.0, 1500.0);
  add("pdu", "pdu",
      {{"max_output_speed", uncertain(w_max, 0.1)}, {"stall_torque", uncertain(stall, 0.15)},
       {"motor_inertia", uncertain(uniform(1e-4, 4e-4), 0.3)}, {"ratio", value(uniform(10.0, 25.0))},
       {"efficiency", efficiency(0.85, 0.95)}});
  const bool two_wings = options.allow_two_wings && coin(0.5);
  std::vector<std::string> actuators;
  for (const std::string& side : two_wings ? std::vector<std::string>{"l", "r"} : std::vector<std::string>{"l"}) {
    std::string previous = "pdu", previous_port = side == "l" ? "left" : "right";
    if (coin(0.7)) {
      const double lockout = uniform(0.3, 0.9) * stall;
      add("stl_" + side, "system_torque_limiter",
          {{"lockout_torque_extend", uncertain(lockout, 0.1)}, {"lockout_torque_retract", uncertain(lockout, 0.1)},
           {"end_stop_torque", uncertain(1.25 * lockout, 0.1)}, {"inertia", coin(0.2) ? value(0.0) : uncertain(1e-3, 0.5)}});
      connect(previous, previous_port, "stl_" + side, "input");
      previous = "stl_" + side;
      previous_port = "output";
    }
    const int stations = 1 + static_cast<int>(uniform(0.0, options.max_stations - 0.001));
    auto shaft = [&](const std::string& id) {
      const double D = uniform(0.035, 0.06), t = uniform(0.0012, 0.003);
      add(id, "torque_shaft",
          {{"length", uncertain(uniform(0.8, 5.0), 0.05)}, {"outer_diameter", uncertain(D, 0.02)},
           {"wall_thickness", uncertain(t, 0.05)}, {"shear_modulus", uncertain(44e9, 0.08)},
           {"drag_per_length", uncertain(uniform(0.1, 0.5), 0.5)}});
    };
    for (int s = 1; s <= stations; ++s) {
      const std::string k = side + std::to_string(s);
      shaft("shaft_" + k);
      connect(previous, previous_port, "shaft_" + k, "a");
      std::string end = "shaft_" + k;
      if (coin(0.3)) {  // a bearing or a joint and a second segment
        const std::string mid = (coin(0.5) ? "bearing_" : "joint_") + k;
        add(mid, mid.rfind("bearing", 0) == 0 ? "steady_bearing" : "universal_joint",
            mid.rfind("bearing", 0) == 0 ? std::map<std::string, Parameter>{{"coulomb_torque", uncertain(0.1, 0.5)}}
                                         : std::map<std::string, Parameter>{{"efficiency", efficiency(0.97, 0.995)}});
        connect(end, "b", mid, "a");
        shaft("shaft_" + k + "b");
        connect(mid, "b", "shaft_" + k + "b", "a");
        end = "shaft_" + k + "b";
      }
      add("tgb_" + k, "branch_gearbox", {{"ratio", uncertain(uniform(1.0, 2.5), 0.02)}, {"eta_mesh", efficiency(0.95, 0.99)}});
      const double limiter = uniform(40.0, 200.0);
      add("slim_" + k, "station_torque_limiter",
          {{"lockout_torque_extend", uncertain(limiter, 0.1)}, {"end_stop_torque", uncertain(1.25 * limiter, 0.1)}});
      add("gra_" + k, "geared_rotary_actuator",
          {{"ratio", uncertain(uniform(100.0, 300.0), 0.02)}, {"eta_opposing", efficiency(0.8, 0.9)},
           {"eta_aiding", efficiency(0.6, 0.8)}, {"output_torque_rating", uncertain(uniform(10e3, 30e3), 0.1)},
           {"input_inertia", uncertain(1e-3, 0.3)}});
      connect(end, "b", "tgb_" + k, "input");
      connect("tgb_" + k, "branch", "slim_" + k, "input");
      connect("slim_" + k, "output", "gra_" + k, "input");
      actuators.push_back("gra_" + k);
      previous = "tgb_" + k;
      previous_port = "through";
    }
    shaft("shaft_" + side + "tip");
    connect(previous, previous_port, "shaft_" + side + "tip", "a");
    add("wtb_" + side, "wing_tip_brake",
        {{"static_capacity", uncertain(uniform(300.0, 900.0), 0.1)}, {"max_dynamic_torque", uncertain(uniform(300.0, 700.0), 0.1)}});
    add("appu_" + side, "position_sensor");
    connect("shaft_" + side + "tip", "b", "wtb_" + side, "a");
    connect("wtb_" + side, "b", "appu_" + side, "a");
  }
  const bool profile = coin(0.5);
  for (const char* direction : {"extend", "retract"}) {
    LoadCase lc;
    lc.name = direction;
    lc.direction = direction;
    const double sign = lc.direction == "extend" ? 1.0 : -1.0;
    for (const auto& a : actuators) {
      const double peak = uniform(2e3, 20e3);
      lc.actuator_loads[a] = {"position", {0.0, 1.0}, {sign * uniform(0.2, 1.0) * peak, sign * peak}};
    }
    if (profile) lc.pdu_speed = Table{"time", {0.0, 0.4, 30.0}, {0.0, w_max, w_max}};
    p.load_cases.push_back(lc);
  }
  return p;
}

}  // namespace highlift::testing
