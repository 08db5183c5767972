// The simulator's side of a drive-system model: the model layer builds the element network
// (model/src/drive_network.cc); here are the simulation options, the derived output columns and
// the peak torques per component.
#include <cmath>
#include <map>

#include "highlift/sim/drive_network.h"

namespace highlift::sim {

SimulationOptions DriveModel::Options(const Project& /*project*/) const {
  SimulationOptions o;
  o.stop_time = stop_time;
  o.relative_tolerance = relative_tolerance;
  o.output_interval = output_interval;
  o.initial_equilibrium = true;  // the drive starts held, the loads acting (airloads on a brake)
  o.torque_tolerance = 1e-3;     // N*m: twists of stiff jams and end stops resolved in torque
  // Speeds resolved relative to the friction speed: below it the regularised friction laws
  // change sign, and a speed error of rtol * w_small moves them by rtol of their amplitude. A
  // stopped shaft is otherwise resolved to 1e-8 rad/s (the absolute tolerance), and its
  // ringing sets the step size of a jam or rupture long after the loads have peaked.
  o.speed_resolution = friction_speed;
  return o;
}

DriveModel BuildDriveNetwork(const Project& project, const DriveNetworkOptions& options) {
  return DriveModel{model::BuildDriveModel(project, options)};
}

DriveModel BuildDriveNetwork(const Project& project, const Scenario* scenario, const DriveNetworkOptions& options) {
  return DriveModel{model::BuildDriveModel(project, scenario, options)};
}

DerivedColumnSink::DerivedColumnSink(std::vector<DerivedColumn> derived, OutputSink& next)
    : derived_(std::move(derived)), next_(next) {}

void DerivedColumnSink::Begin(const std::vector<std::string>& columns) {
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < columns.size(); ++i) index[columns[i]] = static_cast<int>(i);
  std::vector<std::string> all = columns;
  sources_.clear();
  for (const auto& d : derived_) {
    auto it = index.find(d.source);
    if (it == index.end() || index.count(d.name)) continue;
    all.push_back(d.name);
    sources_.emplace_back(it->second, d.factor);
  }
  next_.Begin(all);
}

void DerivedColumnSink::Row(double time, const std::vector<double>& values) {
  if (sources_.empty() || !next_.ReadsValues()) {
    next_.Row(time, values);
    return;
  }
  row_.assign(values.begin(), values.end());
  for (const auto& [i, factor] : sources_) row_.push_back(factor * values[i]);
  next_.Row(time, row_);
}

void DerivedColumnSink::End() { next_.End(); }

std::vector<PeakTorque> ComponentPeakTorques(const DriveModel& model, const Project& project,
                                             const SimulationReport& report) {
  std::map<std::string, PeakTorque> best;
  for (const PeakTorque& p : report.peak_torques) {
    std::string component;
    if (auto it = model.component_of.find(p.element); it != model.component_of.end()) {
      component = it->second;
    } else {
      // A part of a composite ("stl_left.brake"): the longest owner id that prefixes it.
      for (const auto& [id, owner] : model.component_of)
        if (!owner.empty() && p.element.size() > id.size() && p.element.compare(0, id.size(), id) == 0 &&
            p.element[id.size()] == '.' && id.size() > component.size())
          component = owner;
    }
    if (component.empty()) continue;
    const Component* c = project.FindComponent(component);
    if (!c) continue;
    // Scenario parts of an actuator (its airload, its jam) are not its torque.
    if (p.element != component && model.own_element_torque.count(component)) continue;
    PeakTorque q = p;
    q.element = component;
    if (auto sign = model.torque_sign.find(component); sign != model.torque_sign.end())
      q.tau = sign->second * p.tau;  // a shaft: as the derived column <shaft>.tau
    auto it = best.find(component);
    if (it == best.end() || std::abs(q.tau) > std::abs(it->second.tau)) best[component] = q;
  }
  std::vector<PeakTorque> out;
  for (const Component& c : project.components)
    if (auto it = best.find(c.id); it != best.end()) out.push_back(it->second);
  return out;
}

}  // namespace highlift::sim
