// The catalogue of component types: each type declares its ports (flanges and signals) and its
// parameters (name, dimension, display unit, default, valid range) exactly once. The JSON reader,
// the ICSP, the estimator, the database, the reduced models, the simulator and the Modelica
// exporter all read these declarations.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "highlift/core/domain.h"
#include "highlift/core/units.h"

namespace highlift {

enum class PortKind {
  kFlange,  ///< rotational mechanical flange (phi, tau)
  kSignal,  ///< real-valued signal (e.g. a sensor output, a brake command)
  kHydraulic,  ///< hydraulic port (p, V_flow): connected ports form a node with one pressure
};

/// "flange", "signal" or "hydraulic" (reports, JSON, the component reference).
inline const char* PortKindName(PortKind kind) {
  switch (kind) {
    case PortKind::kFlange: return "flange";
    case PortKind::kSignal: return "signal";
    case PortKind::kHydraulic: return "hydraulic";
  }
  return "flange";
}

struct PortSpec {
  std::string name;         ///< e.g. "input", "output", "branch", "left", "right"
  PortKind kind = PortKind::kFlange;
  bool required = true;     ///< validation reports a required port left open
  std::string description;
  bool output = false;      ///< a signal output (y, phi, w, ...); other signal ports are inputs
  /// A geared flange: it turns 1/value as fast as the component's flange "input", value being the
  /// parameter named here (a gear's output: "ratio" = input speed / output speed). Empty: it
  /// turns with "input" (or the type has no gear). The graph's speed ratios, validation's
  /// gear-ratio convention and the model layer's speed law between ports read this.
  std::string speed_ratio;
};

/// What a component type is in the drive system. Validation, the translation into simulation
/// elements, the lumped models, the peak cases, the report and the campaign ask these instead of
/// the type's name (declared once per type, with its ports and parameters).
struct ComponentRoles {
  bool drive_unit = false;    ///< the power drive unit: root of the transmission (one per project)
  bool actuator = false;      ///< drives a surface: carries the load case's airloads, may jam
  bool chain_member = false;  ///< reduced resolution: lumped with its neighbours into one chain
  bool rupturable = false;    ///< a rupture scenario may name it
  bool jammable = false;      ///< a jam scenario may name it
  bool tip_brake = false;     ///< a wing-tip brake: the monitor applies it, the drive unit then shuts down
  bool segment = false;       ///< a distributed segment (torque shaft, parameter "length"): in the lumped
                              ///< models a link with its stiffness and inertia between two points
  bool lumps_inertia = false; ///< in the lumped models a point of inertia is named after it
  bool wing_limiter = false;     ///< limits the torque into a whole wing (system torque limiter): set
                                 ///< against the largest wing torque of every load case; caps a jam's
                                 ///< static torque at its lock-out
  bool station_limiter = false;  ///< limits the torque into one station: set against the station's
                                 ///< torques of each direction; in a jam what lies behind it sees at
                                 ///< most its end-stop torque
  bool tip_sensor = false;    ///< a position sensor (APPU) whose angle and speed the monitor reads

  bool torque_limiter() const { return wing_limiter || station_limiter; }
};

/// What a parameter holds. Scalars (the default) are quantities with a unit and an interval
/// domain; tables are matrices of numbers in SI (e.g. a LossyGear loss table, a TimeTable);
/// booleans and integers are stored in Parameter::nominal; texts in Component::texts.
enum class ParameterKind { kScalar, kInteger, kBoolean, kTable, kText };

/// The side of the gears a rotational parameter is referred to: the flange, and so the speed, at
/// which its value counts. Referring a value across a gear of ratio i = w_in / w_out multiplies a
/// torque, an angle or a speed by i (or 1/i) and an inertia, a stiffness or a damping by i^2: the
/// flap inertia of domain.md s3, 9.7e-3 kg*m^2 at the shaft, is 4 x 9.7e-3 at the input of an
/// actuator behind a 2:1 station gearbox. Every inertia, stiffness, damping and torque parameter
/// of a component type states its side; speeds and angles of a geared flange do where it matters.
enum class ReferenceSide {
  kNone,            ///< not referred to a gear side (lengths, efficiencies, ratios, times, ...)
  kMotor,           ///< one PDU motor: motor speed = PDU ratio x PDU output speed
  kPduOutput,       ///< the PDU output flange (the differential's output, before the STL)
  kShaft,           ///< the transmission shaft: the speed of the torque tubes (= PDU output speed)
  kActuatorInput,   ///< a station actuator's input, behind the station gearbox (station limiter side)
  kActuatorOutput,  ///< a station actuator's output: the flap track or slat pinion
};

/// "none", "motor", "pdu_output", "shaft", "actuator_input", "actuator_output" (JSON, reports).
const char* ToString(ReferenceSide side);
/// The side named by ToString, or nullopt.
std::optional<ReferenceSide> ParseReferenceSide(std::string_view name);
/// "motor side", "PDU output", "shaft side", "actuator input", "actuator output"; "" for kNone
/// (the component reference, `highlift info`).
const char* ReferenceSideLabel(ReferenceSide side);

/// Declaration of one parameter of a component type.
struct ParameterSpec {
  ParameterKind kind = ParameterKind::kScalar;
  std::string name;          ///< full-word snake_case, e.g. "outer_diameter", "stiffness"
  std::string symbol;        ///< physics symbol used in laws and reports, e.g. "D", "c", "J"
  Dimension dimension;       ///< SI dimension
  std::string unit;          ///< display unit, e.g. "mm", "N*m/rad", "kg*m^2"
  std::optional<double> nominal;  ///< default nominal value in SI, when there is a sensible one
  Domain default_domain;     ///< default interval domain in SI (may be unbounded)
  Domain valid_range;        ///< physically valid values in SI; outside is an input error
  std::string description;   ///< one line, with the meaning of the parameter
  std::string source;        ///< where the default comes from (domain.md tag and section)
  ReferenceSide referred_to = ReferenceSide::kNone;  ///< the gear side the value counts on
  bool optional = false;     ///< may be left unknown (e.g. derived from other parameters)
};

/// A bound of one parameter by another that their own valid ranges cannot express:
/// parameter <= bound / divisor (a tube's wall_thickness <= outer_diameter / 2), or with `strict`
/// parameter < bound / divisor (a limiter's lock-out torque below its end stop). Validation
/// reports a violation at `parameter`, naming `meaning` and `note`.
struct ParameterRelation {
  std::string parameter;  ///< e.g. "wall_thickness"
  std::string bound;      ///< e.g. "outer_diameter"
  double divisor = 1.0;   ///< e.g. 2
  std::string meaning;    ///< what bound / divisor is, e.g. "the radius"
  std::string note;       ///< said after the fix, e.g. "equal: a solid shaft"
  bool strict = false;    ///< equality violates the relation too
};

/// Declaration of a component type.
struct ComponentTypeSpec {
  std::string name;          ///< JSON "type", e.g. "torque_shaft"
  std::string display_name;  ///< e.g. "torque shaft"
  std::string description;
  std::vector<PortSpec> ports;
  std::vector<ParameterSpec> parameters;
  ComponentRoles roles;
  std::vector<ParameterRelation> relations;

  const PortSpec* FindPort(std::string_view port) const;
  /// The first flange with a speed_ratio (the type is a gear, entered at its flange "input"),
  /// or nullptr.
  const PortSpec* GearedPort() const;
  const ParameterSpec* FindParameter(std::string_view parameter) const;
};

/// The provider of the component types' declarations: every type, in a fixed order.
using ComponentCatalogueProvider = const std::vector<ComponentTypeSpec>& (*)();
/// Installs the provider. Each type is declared in its own file of the model layer
/// (model/src/components/<type>.cc), above core; the model layer's registry installs them when a
/// program linking highlift::model starts (model/src/components/registry.cc).
void InstallComponentCatalogue(ComponentCatalogueProvider provider);
/// True when a provider is installed.
bool ComponentCatalogueInstalled();

/// All drive-system component types, in a fixed order (the catalogue's, docs/components.md).
/// Throws InternalError when no provider is installed (a program that does not link
/// highlift::model).
const std::vector<ComponentTypeSpec>& ComponentTypes();
/// The type named `name`, or nullptr.
const ComponentTypeSpec* FindComponentType(std::string_view name);

/// All element types of the element-level network (the simulation primitives with Modelica
/// Standard Library names and parameter names: "Inertia" with "J", "Spring" with "c", ...).
const std::vector<ComponentTypeSpec>& ElementTypes();
const ComponentTypeSpec* FindElementType(std::string_view name);

/// The names of all component types, in catalogue order (for messages and listings).
std::vector<std::string> ComponentTypeNames();
/// The names of the component types with a role, in catalogue order, e.g.
/// ComponentTypesWith(&ComponentRoles::actuator).
std::vector<std::string> ComponentTypesWith(bool ComponentRoles::*role);
/// The roles of component type `type`; none for an unknown type.
ComponentRoles RolesOf(std::string_view type);

/// The component reference (docs/components.md) as Markdown, generated from the catalogue:
/// every type with its ports and its parameters with units, defaults, ranges and sources.
std::string CatalogueMarkdown();

/// Closest names to `name` among `candidates` (edit distance), for "did you mean" messages.
std::vector<std::string> Suggest(std::string_view name, const std::vector<std::string>& candidates,
                                 std::size_t max_results = 3);

/// "; did you mean 'a'?" / "; did you mean 'a' or 'b'?", or "" when no candidate is close.
std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates);

/// A message tail naming the valid choices: "; did you mean 'x'? Allowed keys: a, b" or, without
/// a close name, "; allowed keys: a, b" (`label` is "allowed keys", "valid types", ...).
std::string SuggestionHint(std::string_view name, const std::vector<std::string>& candidates,
                           const std::string& label);

}  // namespace highlift
