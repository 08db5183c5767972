// Project-level reduced-model analyses: lumped models and modes of the component graph, and the
// single-DOF peak loads of the sizing cases (jam at every actuator, wing-tip brake application
// after the rupture of every shaft segment), with interval enclosures and parameter ranking.
#pragma once

#include <string>
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
  double tau_static = 0.0; ///< N*m, static drive (jam) or back-drive (rupture) torque
  Bounded tau_total;       ///< N*m, tau_dynamic + tau_static
  std::vector<ParameterShare> ranking;  ///< by share of the tau_dynamic width, largest first
  std::string note;
};

struct ComponentPeak {
  std::string component;
  std::string worst_case;
  Bounded torque;          ///< N*m at the reference (shaft) speed
  double local_torque = 0.0;  ///< N*m at the component's own speed (upper bound)
  std::string allowable_name;
  double allowable = 0.0;  ///< N*m, 0 when the component has none
  double margin = 0.0;     ///< allowable / local_torque - 1 (infinite without allowable)
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
};
/// Throws InputError when `only_case` names no case (listing the cases).
PeakReport AnalysePeaks(const Project& project, const PeakOptions& options = {});

}  // namespace highlift::reduced_models
