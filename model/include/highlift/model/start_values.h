// The state a simulation of an element network starts from, written as start values of the
// network's own flanges, so that the Modelica export can write the simulator's start without
// the simulator: `highlift export` computes them with sim::ComputeStartValues (the same start
// sequence as Simulator::Run: the initial modes and, for a drive system, the static equilibrium
// of the loads held by the parked brakes) and hands them to the writer.
//
// The flanges are an independent set: their angles and speeds, with the gears and the
// elements' own initial values, determine every angle and speed of the network, so a Modelica
// tool gets exactly as many initial equations as the model has states.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "highlift/core/project.h"

namespace highlift::model {

/// The start of one flange of the network.
struct FlangeStart {
  PortRef flange;             ///< "element.port" of the network (an Inertia's flange where one is there)
  std::optional<double> phi;  ///< angle, rad (position, m, for a translational flange): fix it
  std::optional<double> w;    ///< speed, rad/s (m/s): fix it
};

struct StartValues {
  std::vector<FlangeStart> flanges;
  /// How the start was found, one line ("static equilibrium: loads balanced to 2e-09 N*m").
  std::string summary;
  /// Largest disagreement of the twists of the compliant elements with the node angles (rad);
  /// 0 for a network without loops of springs.
  double inconsistency = 0.0;
  /// Free flanges (degrees of freedom) that no flange of the network reaches: the internal
  /// nodes of composites. Empty for every bundled example (a test pins this down).
  std::vector<std::string> unreached;
};

}  // namespace highlift::model
