// Project-level reduced-model analyses: lumped models and modes of the component graph, and the
// single-DOF peak loads of the sizing cases (jam at every actuator, wing-tip brake application
// after the rupture of every shaft segment), with interval enclosures and parameter ranking.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "highlift/core/project.h"
#include "highlift/reduced_models/lumped_model.h"
#include "highlift/reduced_models/sizing.h"

namespace highlift::reduced_models {

/// The lumped model of a project's transmission (nominal values, reflected to the PDU speed).
/// `elements_per_segment` <= 0 takes the project's settings.shaft_elements.
LumpedModel BuildProjectModel(const Project& project, Reduction reduction, int elements_per_segment = 0);

struct ModelModes {
  Reduction reduction = Reduction::kFullResolution;
  int degrees_of_freedom = 0;
  std::vector<double> free_hz;     ///< lowest elastic eigenfrequencies of the free system [Hz]
  std::vector<double> clamped_hz;  ///< lowest eigenfrequencies with the PDU clamped [Hz]
  double first_free_error = 0.0;   ///< relative error of the first elastic free mode vs full resolution
  double first_clamped_error = 0.0;
  std::vector<std::string> node_names;  ///< nodes of the model
  std::vector<std::vector<double>> clamped_shapes;  ///< per mode: shape over the nodes (max |.| = 1)
};

struct ModesReport {
  std::string project;
  int elements_per_segment = 0;
  std::vector<ModelModes> models;  ///< full resolution, accumulated, two masses per section
  std::string BriefReport() const;
  std::string FullReport() const;
  nlohmann::json ToJson() const;
};

struct ModesOptions {
  int elements_per_segment = 0;  ///< sub-elements per shaft segment in the full model; 0: project setting
  int modes = 6;                 ///< number of eigenfrequencies reported per model
};
ModesReport AnalyseModes(const Project& project, const ModesOptions& options = {});

/// First eigenfrequency [rad/s] of the full-resolution model with the PDU clamped.
double FirstEigenfrequency(const Project& project);

struct ParameterShare {
  std::string parameter;  ///< "component.parameter"
  double width = 0.0;     ///< N*m, width of the tau_max enclosure with only this parameter uncertain
  double share = 0.0;     ///< width / sum of the widths
};

struct PeakCase {
  std::string name;        ///< the scenario's name, or "jam_<actuator>" / "rupture_<shaft>"
  std::string kind;        ///< "jam" or "rupture"
  std::string component;   ///< jammed actuator or ruptured shaft
  std::string acts_at;     ///< where tau_max acts: the jammed station, or the wing-tip brake
  std::vector<std::string> load_path;  ///< components carrying the peak (shaft-speed torque)
  double w_max = 0.0;      ///< rad/s at the stop (operating speed for a jam)
  Domain w_max_bounds;
  std::string trigger;     ///< rupture: "overspeed", "asymmetry" or "none"
  double J_star = 0.0;     ///< kg*m^2
  double c_star = 0.0;     ///< N*m/rad
  double omega = 0.0;      ///< rad/s, first eigenfrequency of the part in focus
  double first_mode_share = 0.0;
  Bounded tau_dynamic;     ///< N*m, equation (1)
  double tau_static = 0.0; ///< N*m, static drive (jam) or back-drive (rupture) torque, nominal
  Domain tau_static_bounds;  ///< N*m, its enclosure over the parameter domains
  /// N*m, a jam: the static torque on the drive side of the system torque limiter, the PDU stall
  /// torque before the limiter passes its share on (tau_static behind it); the PDU and what lies
  /// between it and the limiter carry it. Equal to tau_static without a system limiter; a
  /// rupture has none (0, an unbounded domain).
  double tau_static_drive = 0.0;
  Domain tau_static_drive_bounds;  ///< N*m, its enclosure over the parameter domains
  /// N*m at the stop: the largest torque the stop passes before it slips (a friction brake: the
  /// larger of its dynamic and static torques), nominal and over the domains; absent for a rigid
  /// stop (a jam).
  std::optional<Bounded> stop_limit;
  Bounded tau_total;       ///< N*m, tau_dynamic + tau_static, at most stop_limit
  std::vector<ParameterShare> ranking;  ///< by share of the tau_dynamic width, largest first
  std::string note;
  /// A rupture: each back-driven actuator beyond the break, stopped through its station torque
  /// limiter (docs/reduced_models.md, "Actuators in a rupture"): the flap's kinetic energy at the
  /// rupture speed into the limiter's end-stop stiffness plus its back-drive torque, N*m at the
  /// reference (shaft) speed, nominal and over the domains. The actuator and its limiter carry it.
  struct FlapLoad {
    std::string actuator;
    std::string limiter;
    Bounded torque;
  };
  std::vector<FlapLoad> flap_loads;
};

struct ComponentPeak {
  std::string component;
  std::string worst_case;
  Bounded torque;          ///< N*m at the reference (shaft) speed
  double local_torque = 0.0;  ///< N*m at the component's own speed (upper bound over the domains)
  double local_nominal = 0.0;  ///< N*m at the component's own speed, nominal (torque.nominal, nominal ratios)
  std::string allowable_name;
  double allowable = 0.0;      ///< N*m at nominal values, 0 when the component has none
  double allowable_min = 0.0;  ///< N*m, lower bound of the allowable over the domains
  double margin = 0.0;     ///< allowable_min / local_torque - 1: guaranteed lower bound of the margin
                           ///< over the domains (infinite without allowable)
  /// The other side: the largest lower bound of its load over the cases (N*m at the reference
  /// speed, and at its own speed over the largest ratio), the largest allowable over the domains,
  /// and allowable_max / local_torque_certain - 1, an upper bound of the margin over the domains:
  /// negative, no point of the domains meets the allowable (the certain_case's load exceeds it
  /// everywhere); what `highlift optimize` prunes design boxes with.
  double torque_certain = 0.0;
  double local_torque_certain = 0.0;
  std::string certain_case;
  double allowable_max = 0.0;
  double margin_max = 0.0;  ///< infinite without allowable or without a positive certain load
};

struct PeakReport {
  std::string project;
  std::string reduction;
  std::vector<PeakCase> cases;
  std::vector<ComponentPeak> worst;  ///< per component on any load path
  bool ok() const;                   ///< every margin >= 0
  std::string BriefReport() const;
  std::string FullReport() const;
  nlohmann::json ToJson() const;
};

struct PeakOptions {
  /// Sub-elements per shaft segment in the model of the part in focus. The model keeps every
  /// inertia at a fixed place (no lever rule), so w1 is monotone in every c and J and corner
  /// evaluations give a guaranteed enclosure (docs/reduced_models.md).
  int elements_per_segment = 1;
  bool intervals = true;          ///< enclosures over the parameter domains
  bool rank = true;               ///< rank the parameters by their share of the width
  std::string only_case;          ///< empty: every case
  /// Points of the domains at which the cases are evaluated to measure the tightness of the
  /// enclosures (Bounded::tightness of tau_dynamic, tau_total and the worst torques); 0: not measured. Each costs one point evaluation.
  int tightness_samples = 0;
  std::uint64_t tightness_seed = 1;  ///< seed of the sampler (sampling.h)
};
/// Throws InputError when `only_case` names no case (listing the cases).
PeakReport AnalysePeaks(const Project& project, const PeakOptions& options = {});
/// Fills the tightness of the enclosures of `report` (made by AnalysePeaks with intervals) from
/// options.tightness_samples point evaluations (AnalysePeaks calls it when that is > 0).
void MeasureTightness(const Project& project, const PeakOptions& options, PeakReport* report);

}  // namespace highlift::reduced_models

namespace highlift::reduced_models {

/// The structure of the sizing cases of AnalysePeaks, for constraint solvers that rebuild the
/// same single-DOF physics over their own parameter domains (icsp): the component graph seen from
/// the PDU, and per case the transmission in focus with the stop, so that a caller can fill in
/// the reflected inertias and stiffnesses, build the lumped model (BuildLumpedModel with
/// `elements` sub-elements) and take its first eigenfrequency with the stop clamped.
struct PeakGraphNode {
  std::string id;           ///< component id
  std::string type;         ///< component type
  int parent = -1;          ///< index of the upstream node, -1 for the PDU
  std::string gear;         ///< the gearbox whose ratio divides the speed from the parent to this
                            ///< node (an angle gearbox's output, a branch gearbox's branch); empty if none
  std::vector<int> children;
};

struct PeakCaseStructure {
  std::string name;                    ///< as PeakCase::name
  std::string kind;                    ///< "jam" or "rupture"
  std::string component;               ///< jammed actuator or ruptured shaft
  std::string acts_at;                 ///< jammed station or wing-tip brake
  std::vector<std::string> load_path;  ///< as PeakCase::load_path
  int root = -1;                       ///< graph node the part in focus starts at (-1: the whole graph)
  std::vector<int> part;               ///< graph nodes in focus
  Transmission transmission;           ///< the part in focus at nominal values
  std::vector<int> point_of_node;      ///< per graph node: the point holding its concentrated inertia (-1 outside)
  std::vector<int> link_of_node;       ///< per graph node: its link (shaft or elastic component), -1 if none
  int stop_point = -1;                 ///< the transmission point that is clamped
  std::string sensor;                  ///< rupture: the position sensor whose thresholds trip the brake ("" none)
  std::string brake;                   ///< rupture: the wing-tip brake
};

struct PeakStructure {
  std::vector<PeakGraphNode> nodes;            ///< parents before children
  int elements_per_segment = 1;                ///< sub-elements per link in the lumped model
  double w_operating = 0.0;                    ///< rad/s, largest PDU speed of the load cases
  double w_reference = 0.0;                    ///< rad/s, the PDU's max_output_speed (overspeed reference)
  std::map<std::string, double> aiding;        ///< actuator -> aiding output torque (<= 0) of the rupture
  std::vector<PeakCaseStructure> cases;        ///< same order and names as AnalysePeaks
};
/// The structure behind AnalysePeaks(project, options) (options.only_case is ignored).
PeakStructure DescribePeaks(const Project& project, const PeakOptions& options = {});

/// The value the reduced models read for a parameter: the component's own, else the catalogue
/// default (throws InputError naming the parameter when there is none).
double ReducedModelValue(const Component& component, std::string_view name);
/// Whether the reduced models find a value for the parameter (own or catalogue default).
bool HasReducedModelValue(const Component& component, std::string_view name);

}  // namespace highlift::reduced_models
