// Internal: composite element types. A composite (WingTipBrake, TorqueLimiter, PDU, ...) is a
// small network of other element types; the system flattens composites, recursively, before it
// assembles the model, so that a composite needs no law of its own. The project and the Modelica
// export keep the composite as one instance.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "highlift/sim/network.h"

namespace highlift::sim::detail {

/// The parts of one composite instance.
struct Composite {
  /// Parts and their internal connections. One part may keep the composite's own id (its
  /// outputs are reported under that name, e.g. "stl_left.y"); the others are "<id>.<part>".
  Network inner;
  /// Composite port -> inner "element.port": exactly one for a flange or a signal output, one or
  /// more for a signal input (each inner input is connected to the same source).
  std::map<std::string, std::vector<std::string>> ports;
};

/// The expansion of `element` if its type is a composite of the family, else std::nullopt.
std::optional<Composite> ExpandBrakeComposite(const NetworkElement& element);
std::optional<Composite> ExpandGearComposite(const NetworkElement& element);
std::optional<Composite> ExpandDriveComposite(const NetworkElement& element);
std::optional<Composite> ExpandHydraulicComposite(const NetworkElement& element);
/// MSL composites (msl_extra_elements.cc): Gearbox.
std::optional<Composite> ExpandMslComposite(const NetworkElement& element);

/// `network` with every composite replaced by its parts (recursively, at most 8 levels).
/// Throws InputError when an expansion is inconsistent (a part id outside the composite's name
/// space, a connected port the composite does not map). With `ports`, each port "element.port"
/// of a composite of `network` (at any level) is mapped to the inner ports of the flat network
/// it became.
Network FlattenComposites(const Network& network,
                          std::map<std::string, std::vector<std::string>>* ports = nullptr);

}  // namespace highlift::sim::detail
