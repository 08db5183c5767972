// The optimize tests' small chain with an analytic optimum: PDU -> one titanium tube (2 m) ->
// wing-tip brake. Design: D in [20, 60] mm, t in [0.5, 4] mm; requirements: torque capacity
// (at the lesser of the allowable shear stress and the torsional buckling stress) >= 1500 N*m and
// stiffness >= 5000 N*m/rad. The stiffness binds at the optimum (60 x 1.44 mm at 44 GPa, D/t 42,
// where the tube buckles at 1623 N*m with nu at 0.31); at 2000 N*m buckling binds
// (optimize_test.cc, TheLightestTubeRespectsTorsionalBuckling).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "highlift/core/project_io.h"

namespace highlift::testing {

inline nlohmann::json OneTubeChain(const std::string& shear_modulus = "44 GPa", const std::string& capacity = "1500 N*m") {
  nlohmann::json j = nlohmann::json::parse(R"json({
  "format": "highlift-project/1",
  "name": "one tube",
  "components": [
    {"id": "pdu", "type": "pdu", "parameters": {"motor_count": 2, "motor_inertia": "3e-4 kg*m^2",
      "ratio": 20, "gear_inertia": "0.02 kg*m^2"}},
    {"id": "shaft_1", "type": "torque_shaft", "labels": {"side": "left"},
     "parameters": {"length": "2 m",
                    "outer_diameter": {"value": 40, "min": 20, "max": 60, "unit": "mm", "design": true},
                    "wall_thickness": {"value": 2, "min": 0.5, "max": 4, "unit": "mm", "design": true},
                    "density": "4420 kg/m^3", "shear_modulus": "44 GPa", "allowable_shear_stress": "500 MPa"}},
    {"id": "wtb", "type": "wing_tip_brake", "labels": {"side": "left"}, "parameters": {"inertia": "5e-4 kg*m^2"}}
  ],
  "connections": [["pdu.left", "shaft_1.a"], ["shaft_1.b", "wtb.a"]],
  "requirements": [
    {"id": "capacity", "expression": "shaft_1.torque_capacity >= CAPACITY", "description": "ultimate torque"},
    {"id": "stiffness", "expression": "shaft_1.c >= 5000 N*m/rad", "description": "torsional stiffness"}
  ]
})json");
  j["components"][1]["parameters"]["shear_modulus"] = shear_modulus;
  j["requirements"][0]["expression"] = "shaft_1.torque_capacity >= " + capacity;
  return j;
}

inline Project LoadChain(const nlohmann::json& j) { return ParseProject(j.dump(), "chain.json"); }

}  // namespace highlift::testing
