// Component types as units: one ComponentModel per catalogue type, in one file of
// model/src/components/ (its expansion into elements, its speed ratio between ports, its
// contribution to a lumped chain, its role in the scenario parts), registered by one line in
// model/src/components/registry.cc. The translation of a project (drive_network.h) walks the
// component graph and asks each component's model; it never switches on a type name.
//
//   const ComponentModel* m = FindComponentModel(component.type);
//   if (m && m->roles().actuator) ...
//   m->Expand(component, context);   // adds the component's elements to the network
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "highlift/core/catalogue.h"
#include "highlift/core/project.h"
#include "highlift/model/estimation_laws.h"
#include "highlift/model/interval.h"
#include "highlift/model/laws.h"
#include "highlift/model/network.h"
#include "highlift/model/symbolic.h"

namespace highlift::model {

struct DriveModel;

/// Parameter values of an element in SI, by parameter name.
using Scalars = std::map<std::string, double>;

/// What a component type is in the drive system: declared with its ports and parameters in the
/// catalogue (core/catalogue.h), read here through ComponentModel::roles().
using ComponentRoles = highlift::ComponentRoles;

/// The values of a component's parameters as a law reads them, for scalar T: double (nominal
/// values), Interval (domains, for enclosures) or Sym (the propagator's variables, symbolic.h).
/// Implemented by each analysis over its own notion of a value (reduced_models: nominal, all
/// domains, or one parameter's domain; icsp: the parameter's variable, or Sym::Missing).
template <class T>
class ParameterReader {
 public:
  virtual ~ParameterReader() = default;
  /// The value; throws InputError naming the component and parameter when there is none.
  virtual T operator()(std::string_view name) const = 0;
  /// True when the parameter has a value (given, or a catalogue default).
  virtual bool Has(std::string_view name) const = 0;
  /// The nominal value, also when T is an interval (counts such as motor_count).
  virtual double Nominal(std::string_view name) const = 0;
};

/// A component's contribution to the lumped models at its own input speed.
template <class T>
struct Lumped {
  T J = T(0.0);          ///< kg*m^2, concentrated inertia (a segment: its distributed inertia)
  std::optional<T> c;    ///< N*m/rad, stiffness in the power path (absent: rigid)
};

/// The default lumped law: the parameter "inertia" if it has a value, else none; the optional
/// parameter "stiffness" if it has a value, else rigid.
template <class T>
Lumped<T> DefaultLumped(const ParameterReader<T>& p) {
  Lumped<T> out;
  if (p.Has("inertia")) out.J = p("inertia");
  if (p.Has("stiffness")) out.c = p("stiffness");
  return out;
}

/// What a component carries in the steady state (the torque flow of the sizing), for scalar T.
/// Torques are positive when they resist the commanded motion.
template <class T>
struct SteadyFlow {
  T through = T(0.0);   ///< N*m, torque taken at its outgoing ports but "branch" (at their speed)
  T branch = T(0.0);    ///< N*m, torque taken at its port "branch"
  T load = T(0.0);      ///< N*m, an actuator's output load of the load case
  T w = T(0.0);         ///< rad/s, speed of its input flange
  T friction = T(1.0);  ///< 1: with its drag and friction, 0: without
};

/// The speed law between two ports: speed(to) / speed(from) = value(parameter)^power, with
/// power -1, 0 or 1 (no parameter: 1).
struct PortRatio {
  std::string_view parameter;
  int power = 0;
};

/// The ports of the drive unit as "element.port" in the network.
struct DriveUnitPorts {
  std::string flange_left;   ///< output flange to the left transmission
  std::string flange_right;  ///< output flange to the right transmission
  std::string w_ref;         ///< signal input: commanded output speed, rad/s
  std::string phi;           ///< signal output: output angle, rad
  std::string stop;          ///< signal input: shutdown command (> 0.5), empty when it has none
};

/// A member of a lumped chain (reduced resolution): what it adds to the chain's spring-damper
/// (in series) and to its end inertias.
struct ChainMember {
  double J = 0;                ///< kg*m^2, inertia
  double drag = 0;             ///< N*m, Coulomb drag
  std::optional<double> c;     ///< N*m/rad, stiffness (absent: rigid)
  std::optional<double> d;     ///< N*m*s/rad, damping in series with the others (absent or 0: none)
  bool torque_column = false;  ///< reports "<id>.tau", the chain spring's torque (torque shafts)
};

/// An allowable torque of a component for the margins of the sizing and the peak loads.
template <class T>
struct Allowable {
  std::string name;  ///< what it is, e.g. "torque capacity at the allowable shear stress"
  T value = T(0.0);  ///< N*m
  /// Steady state: false, set against the torque at its input flange at its own speed; true,
  /// against its output load of the load cases (an actuator's output torque rating).
  bool against_output_load = false;
};

/// A sizing rule of a setting (a limiter's lock-out torque, a brake's capacity): the recommended
/// value is `factor` x the torque it is set against, acceptable within [factor_min, factor_max].
struct SettingRule {
  /// The torque a setting is set against, at the component's own speed.
  enum class Against {
    kOperating,         ///< the largest operating torque over every load case
    kOperatingExtend,   ///< ... over the extend load cases (every case when there is none)
    kOperatingRetract,  ///< ... over the retract load cases (every case when there is none)
    /// the larger of the wing's operating torque at its root (over every load case) and its
    /// back-drive torque (its airloads through the aiding efficiencies, friction neglected)
    kWingHolding,
    /// what a jam behind a torque limiter makes it ground: the static torque the drive can put
    /// into it (the PDU stall torque through the system torque limiters on its path, at its
    /// own speed) minus its end-stop torque (LimiterPassedTorque of torque_limiter.h)
    kJamGrounding,
  };
  std::string parameter;  ///< the setting, e.g. "lockout_torque_extend"
  std::string rule;       ///< the rule in words with its source
  Against against = Against::kOperating;
  double factor = 1.0;
  double factor_min = 1.0;
  double factor_max = 1.0;
};

/// The services of the translation to a component's expansion (implemented by the builder of
/// model/src/drive_network.cc).
class ExpansionContext {
 public:
  virtual ~ExpansionContext() = default;
  virtual const Project& project() const = 0;
  /// The scenario applied, or nullptr.
  virtual const Scenario* scenario() const = 0;
  /// Spring-dampers per torque shaft at full resolution.
  virtual int shaft_elements() const = 0;
  /// The project's structural damping beta, s: d = beta*c for elastic elements without their own.
  virtual double beta() const = 0;
  /// `s` with the friction regularisation w_small of the options, when it is on.
  virtual Scalars Regularised(Scalars s) const = 0;
  /// Adds element `id` (the component's id or "<id>.<part>") of element type `type` to the
  /// network, belonging to `component`; `description` is the line the export writes as comment
  /// (empty: the component's description for the element that is the component itself).
  virtual void Add(const std::string& type, const std::string& id, Scalars scalars, const std::string& component,
                   std::map<std::string, Table> tables = {}, std::string description = {}) = 0;
  virtual void Connect(const std::string& a, const std::string& b) = 0;
  /// The element port that stands for the component's port `port`.
  virtual void MapPort(const Component& c, const std::string& port, const std::string& ref) = 0;
  /// The network and the model under construction (sub-networks, derived columns).
  virtual Network& network() = 0;
  virtual DriveModel& model() = 0;
  /// Declares the drive unit; the translation connects the speed command and the shutdown.
  virtual void SetDriveUnit(const Component& c, const DriveUnitPorts& ports) = 0;
  /// A wing-tip brake, applied by the monitor's command (input "apply" of element `c.id`).
  virtual void AddTipBrake(const Component& c) = 0;
  /// A tip position sensor (APPU) whose angle and speed the monitor reads at `c.id`.flange_a.
  virtual void AddTipSensor(const Component& c) = 0;
  /// True when the project has tip brakes (then the drive unit needs its shutdown input).
  virtual bool HasTipBrakes() const = 0;
};

/// One catalogue component type, everything the translation needs to know about it.
class ComponentModel {
 public:
  virtual ~ComponentModel() = default;
  /// The catalogue name (JSON "type").
  virtual std::string_view type() const = 0;
  /// The roles its catalogue declaration gives it.
  ComponentRoles roles() const;
  /// The speed law between two ports. Default: by the declaration's geared flanges
  /// (PortSpec::speed_ratio; a gear's output turns 1/ratio as fast as its input); none otherwise.
  virtual PortRatio SpeedRatioLaw(std::string_view from, std::string_view to) const;
  /// Speed at port `to` / speed at port `from` by SpeedRatioLaw at the component's nominal
  /// values. Throws InputError when a ratio has no value.
  double SpeedRatio(const Component& c, std::string_view from, std::string_view to) const;
  /// The ports through which power leaves the component when it is entered at its near port
  /// ("input" or "a"; the drive unit is the root), in the order the analyses visit them.
  virtual std::vector<std::string> PowerPorts() const { return {"b"}; }
  /// The contribution to the lumped models (lumped_model.h of reduced_models) for each scalar.
  virtual Lumped<double> LumpedAtInput(const ParameterReader<double>& p) const { return DefaultLumped(p); }
  virtual Lumped<Interval> LumpedAtInput(const ParameterReader<Interval>& p) const { return DefaultLumped(p); }
  virtual Lumped<Sym> LumpedAtInput(const ParameterReader<Sym>& p) const { return DefaultLumped(p); }
  /// The steady-state law: the torque at its input flange, at its own speed (gear stages with
  /// their opposing/aiding efficiencies, drag by the Stribeck law). Default: what it passes on.
  virtual double InputTorque(const ParameterReader<double>&, const SteadyFlow<double>& in) const { return in.through; }
  virtual Interval InputTorque(const ParameterReader<Interval>&, const SteadyFlow<Interval>& in) const {
    return in.through;
  }
  virtual Sym InputTorque(const ParameterReader<Sym>&, const SteadyFlow<Sym>& in) const { return in.through; }
  /// Its allowable torque in the steady-state margins (`highlift size`); none by default.
  virtual std::optional<Allowable<Interval>> SteadyAllowable(const ParameterReader<Interval>&) const {
    return std::nullopt;
  }
  /// Its allowable torque at its input flange against the peak loads (`highlift peak`): nominal
  /// and over the domains; none by default.
  virtual std::optional<Allowable<double>> PeakAllowable(const ParameterReader<double>&) const { return std::nullopt; }
  virtual std::optional<Allowable<Interval>> PeakAllowable(const ParameterReader<Interval>&) const {
    return std::nullopt;
  }
  /// The sizing rules of its settings (`highlift size` recommends them); none by default.
  virtual std::vector<SettingRule> SettingRules() const { return {}; }
  /// The port whose power passes through its torque limiter (a limiter role): its settings are
  /// set against, and in a jam cap, the torque leaving at this port, at this port's speed (the
  /// torque at the input of what is connected there). Empty (default): the torque at its input
  /// flange, the limiter being in line (a station or system torque limiter).
  virtual std::string_view LimitedPort() const { return {}; }
  /// Adds the component's elements (full resolution; at reduced resolution the chain members
  /// are lumped by the translation from ChainMember). Throws InputError naming the component and
  /// parameter for a value it cannot translate.
  virtual void Expand(const Component& c, ExpansionContext& context) const = 0;
  /// A chain member's contribution to its lumped chain (roles().chain_member only).
  virtual ChainMember Chain(const Component& c, double beta) const;
  /// An actuator's output angle over its full travel, rad (roles().actuator only): the abscissa
  /// of airload tables against position.
  virtual double TravelAngle(const Component& c) const;
  /// An actuator's travel at its input flange over its full travel, rad (the output angle times
  /// its ratio), as the propagator's expression; Sym::Missing for a type that is no actuator.
  virtual Sym InputTravel(const ParameterReader<Sym>& p) const;
  /// Its estimation laws (estimation_laws.h), in the order the estimator applies them.
  virtual std::vector<EstimationLaw> EstimationLaws() const { return {}; }
  /// Its parameters that the estimator fits against a rating over the database parts of its type.
  virtual std::vector<FitRule> FitRules() const { return {}; }
  /// When it is the stop of a peak case (the brake after a rupture): the largest torque it can
  /// pass to ground at its flange, above which it slips (a friction brake); nullopt: a rigid stop
  /// (the default), which takes whatever the single-DOF estimate puts into it.
  virtual std::optional<double> StopTorqueLimit(const ParameterReader<double>&) const { return std::nullopt; }
  virtual std::optional<Interval> StopTorqueLimit(const ParameterReader<Interval>&) const { return std::nullopt; }
  virtual std::optional<Sym> StopTorqueLimit(const ParameterReader<Sym>&) const { return std::nullopt; }
  /// A torque limiter in a jam behind it (the jammed actuator beyond its limited port): the
  /// torque it passes on to what lies behind it when `tau_in` arrives at its input, both in the
  /// units of `n` x its own torque (n = its limited node's speed / the reference speed; n = 1:
  /// at its own speed); nullopt: it passes everything (the default). The law is
  /// LimiterPassedTorque of torque_limiter.h, docs/reduced_models.md "The station torque limiter
  /// in a jam".
  virtual std::optional<double> JamPassedTorque(const ParameterReader<double>&, const double& /*tau_in*/,
                                                const double& /*n*/) const {
    return std::nullopt;
  }
  virtual std::optional<Interval> JamPassedTorque(const ParameterReader<Interval>&, const Interval& /*tau_in*/,
                                                  const Interval& /*n*/) const {
    return std::nullopt;
  }
  virtual std::optional<Sym> JamPassedTorque(const ParameterReader<Sym>&, const Sym& /*tau_in*/,
                                             const Sym& /*n*/) const {
    return std::nullopt;
  }
};

/// In a ComponentModel: overrides the three LumpedAtInput with the member template
/// `template <class T> Lumped<T> Law(const ParameterReader<T>&) const`, the law written once.
#define HIGHLIFT_LUMPED_LAW                                                                            \
  Lumped<double> LumpedAtInput(const ParameterReader<double>& p) const override { return Law(p); }   \
  Lumped<Interval> LumpedAtInput(const ParameterReader<Interval>& p) const override { return Law(p); } \
  Lumped<Sym> LumpedAtInput(const ParameterReader<Sym>& p) const override { return Law(p); }

/// In a ComponentModel: overrides the three InputTorque with the member template
/// `template <class T> T SteadyLaw(const ParameterReader<T>&, const SteadyFlow<T>&) const`.
#define HIGHLIFT_STEADY_LAW                                                                               \
  double InputTorque(const ParameterReader<double>& p, const SteadyFlow<double>& in) const override {      \
    return SteadyLaw(p, in);                                                                              \
  }                                                                                                       \
  Interval InputTorque(const ParameterReader<Interval>& p, const SteadyFlow<Interval>& in) const override { \
    return SteadyLaw(p, in);                                                                              \
  }                                                                                                       \
  Sym InputTorque(const ParameterReader<Sym>& p, const SteadyFlow<Sym>& in) const override {              \
    return SteadyLaw(p, in);                                                                              \
  }

/// In a ComponentModel: overrides both PeakAllowable with the member template
/// `template <class T> std::optional<Allowable<T>> PeakLaw(const ParameterReader<T>&) const`.
#define HIGHLIFT_PEAK_ALLOWABLE_LAW                                                                     \
  std::optional<Allowable<double>> PeakAllowable(const ParameterReader<double>& p) const override {     \
    return PeakLaw(p);                                                                                  \
  }                                                                                                     \
  std::optional<Allowable<Interval>> PeakAllowable(const ParameterReader<Interval>& p) const override { \
    return PeakLaw(p);                                                                                  \
  }

/// In a ComponentModel: overrides the three StopTorqueLimit with the member template
/// `template <class T> std::optional<T> StopLaw(const ParameterReader<T>&) const`.
#define HIGHLIFT_STOP_LIMIT_LAW                                                                        \
  std::optional<double> StopTorqueLimit(const ParameterReader<double>& p) const override { return StopLaw(p); } \
  std::optional<Interval> StopTorqueLimit(const ParameterReader<Interval>& p) const override {         \
    return StopLaw(p);                                                                                 \
  }                                                                                                    \
  std::optional<Sym> StopTorqueLimit(const ParameterReader<Sym>& p) const override { return StopLaw(p); }

/// In a ComponentModel: overrides the three JamPassedTorque with the member template
/// `template <class T> std::optional<T> PassLaw(const ParameterReader<T>&, const T& tau_in, const T& n) const`.
#define HIGHLIFT_JAM_PASSED_LAW                                                                          \
  std::optional<double> JamPassedTorque(const ParameterReader<double>& p, const double& tau_in, const double& n) \
      const override {                                                                                  \
    return PassLaw(p, tau_in, n);                                                                       \
  }                                                                                                     \
  std::optional<Interval> JamPassedTorque(const ParameterReader<Interval>& p, const Interval& tau_in,     \
                                          const Interval& n) const override {                            \
    return PassLaw(p, tau_in, n);                                                                       \
  }                                                                                                     \
  std::optional<Sym> JamPassedTorque(const ParameterReader<Sym>& p, const Sym& tau_in, const Sym& n) const override { \
    return PassLaw(p, tau_in, n);                                                                       \
  }

/// The declarations of every component type (ports, parameters, roles: the Declaration() in each
/// type's file), in catalogue order.
const std::vector<ComponentTypeSpec>& ComponentCatalogue();
/// Installs ComponentCatalogue() as core's catalogue (highlift::ComponentTypes). Done when a
/// program linking highlift::model starts; needed again only after installing another provider.
void InstallComponentCatalogue();

/// The model of component type `type`, or nullptr.
const ComponentModel* FindComponentModel(std::string_view type);
/// Every component model, in catalogue order.
const std::vector<const ComponentModel*>& ComponentModels();
/// The names of the types with a role, in catalogue order (for messages): e.g. the actuators.
std::vector<std::string> TypesWithRole(bool ComponentRoles::*role);

/// Thresholds of the failure monitor, from a tip position sensor (APPU) or, without one, from
/// the catalogue defaults of the position sensor type (position_sensor.cc).
struct MonitorThresholds {
  double phi_asym = 0;        ///< rad, asymmetry threshold at the PDU shaft
  double overspeed_factor = 0;  ///< overspeed threshold / PDU max output speed
  double t_detect = 0;        ///< s, detection latency
};
MonitorThresholds MonitorSettings(const Component* tip_sensor);

/// The mass of a distributed segment (roles().segment) [kg]: its linear density times its length
/// when it gives one, else the tube law (laws.h).
template <class T>
T SegmentMass(const ParameterReader<T>& p) {
  if (p.Has("linear_density")) return p("linear_density") * p("length");
  return ShaftMass(p("density"), p("outer_diameter"), p("wall_thickness"), p("length"));
}

}  // namespace highlift::model
