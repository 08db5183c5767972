// A small one-wing project built through the C++ API (no file): PDU, STL, three stations
// (branch gearbox 2:1 + station limiter + GRA 200:1) on titanium tubes, a WTB and an APPU.
#pragma once

#include <string>

#include "highlift/core/project.h"

namespace highlift::reduced_models::test_projects {

inline Parameter Value(double v) {
  Parameter p;
  p.nominal = v;
  p.domain = Domain::Point(v);
  p.provenance = Provenance::kUser;
  return p;
}
inline Parameter Range(double v, double lo, double hi) {
  Parameter p = Value(v);
  p.domain = {lo, hi};
  return p;
}

inline Project OneWingProject() {
  Project p;
  p.name = "one wing";
  auto add = [&](std::string id, std::string type, std::map<std::string, Parameter> parameters = {}) {
    Component c;
    c.id = std::move(id);
    c.type = std::move(type);
    c.parameters = std::move(parameters);
    p.components.push_back(std::move(c));
  };
  auto connect = [&](std::string a_component, std::string a_port, std::string b_component, std::string b_port) {
    p.connections.push_back({{a_component, a_port}, {b_component, b_port}, {}});
  };
  add("pdu", "pdu", {{"max_output_speed", Value(25.3)}, {"stall_torque", Value(500.0)}});
  add("stl", "system_torque_limiter", {{"lockout_torque_extend", Value(200.0)}});
  connect("pdu", "left", "stl", "input");
  std::string previous = "stl", previous_port = "output";
  for (int s = 1; s <= 3; ++s) {
    const std::string k = std::to_string(s);
    add("shaft_" + k, "torque_shaft",
        {{"length", Value(3.5)}, {"outer_diameter", Value(0.050)}, {"wall_thickness", Range(0.002, 0.0019, 0.0021)},
         {"shear_modulus", Range(44e9, 43e9, 51e9)}});
    add("tgb_" + k, "branch_gearbox", {{"ratio", Value(2.0)}});
    add("slim_" + k, "station_torque_limiter");
    add("gra_" + k, "geared_rotary_actuator", {{"ratio", Value(200.0)}});
    connect(previous, previous_port, "shaft_" + k, "a");
    connect("shaft_" + k, "b", "tgb_" + k, "input");
    connect("tgb_" + k, "branch", "slim_" + k, "input");
    connect("slim_" + k, "output", "gra_" + k, "input");
    previous = "tgb_" + k;
    previous_port = "through";
  }
  add("shaft_tip", "torque_shaft",
      {{"length", Value(1.5)}, {"outer_diameter", Value(0.045)}, {"wall_thickness", Value(0.0018)}});
  add("wtb", "wing_tip_brake");
  add("appu", "position_sensor");
  connect(previous, previous_port, "shaft_tip", "a");
  connect("shaft_tip", "b", "wtb", "a");
  connect("wtb", "b", "appu", "a");
  for (const char* direction : {"extend", "retract"}) {
    LoadCase lc;
    lc.name = std::string(direction) + "_case";
    lc.direction = direction;
    const double sign = lc.direction == "extend" ? 1.0 : -1.0;
    for (int s = 1; s <= 3; ++s) lc.actuator_loads["gra_" + std::to_string(s)] = {"position", {0.0, 1.0}, {sign * 5e3, sign * 20e3}};
    lc.pdu_speed = Table{"time", {0.0, 0.4, 30.0}, {0.0, 25.3, 25.3}};
    p.load_cases.push_back(lc);
  }
  return p;
}

}  // namespace highlift::reduced_models::test_projects
