// The design problem of bench/optimize (issue 29's targets) on a bundled example, shared by the
// benchmark and the optimize tests that pin it down: every torque shaft's outer diameter (0.6-1.2 x
// the example's value) and wall (0.4-2 x), every limiter's extend lock-out setting and every
// wing-tip brake's static capacity over their domains, every station limiter's brake torque
// 0.5-8 x the example's value (the examples' brakes are below size's rule); with `ratio`, every
// geared rotary actuator's ratio over 100-300:1 (domain.md s6). The tube geometry and the ratios
// are marked before estimating, so that the estimator leaves what follows from them by a law (a
// tube's stiffness and inertia) to the network, as `highlift optimize` does.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "highlift/componentdb/database.h"
#include "highlift/core/project_io.h"
#include "highlift/estimation/estimator.h"
#include "highlift/optimize/optimize.h"

namespace highlift::testing {

/// `example`: a file name in examples/; `database`: the estimator's (nullptr: physics estimates
/// only).
inline Project BenchmarkDesignProblem(const std::string& example, bool ratio,
                                      const componentdb::ComponentDatabase* database) {
  Project project = LoadProject(std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "examples" / example);
  // A parameter's domain lo..hi times its nominal value, a design variable.
  auto scale = [](Component& c, const std::string& name, double lo, double hi) {
    const auto it = c.parameters.find(name);
    if (it == c.parameters.end() || !it->second.nominal) return;
    it->second.domain = {lo * *it->second.nominal, hi * *it->second.nominal};
    it->second.design = true;
  };
  for (Component& c : project.components) {
    if (c.type == "torque_shaft") {
      scale(c, "outer_diameter", 0.6, 1.2);
      scale(c, "wall_thickness", 0.4, 2.0);
    }
    if (ratio && c.type == "geared_rotary_actuator") {
      Parameter& r = c.parameters.at("ratio");
      r.domain = {100.0, 300.0};
      r.design = true;
    }
  }
  estimation::EstimateProject(project, database, {});
  for (Component& c : project.components) {
    auto mark = [&](const std::string& name) {
      const auto it = c.parameters.find(name);
      if (it != c.parameters.end() && it->second.domain.width() > 0) it->second.design = true;
    };
    if (c.type == "station_torque_limiter" || c.type == "system_torque_limiter") mark("lockout_torque_extend");
    if (c.type == "station_torque_limiter") scale(c, "max_brake_torque", 0.5, 8.0);
    if (c.type == "wing_tip_brake") mark("static_capacity");
  }
  return project;
}

/// Options::same_value for BenchmarkDesignProblem(..., true, ...): every geared rotary actuator's
/// ratio marked as a design variable, one value (the first actuator's); empty when fewer than two.
inline std::vector<std::vector<std::string>> SameRatio(const Project& project) {
  std::vector<std::string> group;
  for (const Component& c : project.components)
    if (c.type == "geared_rotary_actuator" && c.parameters.count("ratio") && c.parameters.at("ratio").design)
      group.push_back(c.id + ".ratio");
  if (group.size() < 2) return {};
  return {group};
}

/// Each designed tube's slenderness D/t (its torsional buckling stress falls as (t/r)^(3/2)): the
/// shafts whose outer diameter and wall are both in `design`, in the order of their diameters.
inline std::vector<std::pair<std::string, double>> TubeSlenderness(const std::vector<optimize::DesignValue>& design) {
  const std::string diameter = ".outer_diameter";
  std::vector<std::pair<std::string, double>> out;
  for (const optimize::DesignValue& d : design) {
    if (d.name.size() < diameter.size() ||
        d.name.compare(d.name.size() - diameter.size(), diameter.size(), diameter) != 0)
      continue;
    const std::string shaft = d.name.substr(0, d.name.size() - diameter.size());
    for (const optimize::DesignValue& w : design)
      if (w.name == shaft + ".wall_thickness" && w.value_si > 0) out.push_back({shaft, d.value_si / w.value_si});
  }
  return out;
}

}  // namespace highlift::testing
