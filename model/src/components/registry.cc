// The component registry: one line per component type (its declaration and its model are in
// <type>.cc beside this file). The order is the catalogue's. The registry installs the
// declarations as core's catalogue (highlift::ComponentTypes) when the program starts: every
// program linking highlift::model links this file, since model/CMakeLists.txt makes the linker
// keep it (-u highlift_model_component_registry).
#include <algorithm>
#include <unordered_map>

#include "component_util.h"
#include "highlift/core/catalogue.h"
#include "highlift/core/text_table.h"

#define HIGHLIFT_COMPONENT_TYPES(X) \
  X(Pdu)                            \
  X(SystemTorqueLimiter)            \
  X(TorqueShaft)                    \
  X(SteadyBearing)                  \
  X(UniversalJoint)                 \
  X(AngleGearbox)                   \
  X(BranchGearbox)                  \
  X(StationTorqueLimiter)           \
  X(StationInputGearbox)            \
  X(GearedRotaryActuator)           \
  X(BallscrewActuator)              \
  X(WingTipBrake)                   \
  X(PositionSensor)                 \
  X(Disconnector)                   \
  X(Jam)

namespace highlift::model {
namespace components {
#define HIGHLIFT_DECLARE(Name)             \
  ComponentTypeSpec Name##Declaration(); \
  const ComponentModel& Name##Component();
HIGHLIFT_COMPONENT_TYPES(HIGHLIFT_DECLARE)
#undef HIGHLIFT_DECLARE

double Require(const Component& c, const std::string& name) {
  auto it = c.parameters.find(name);
  if (it == c.parameters.end() || !it->second.nominal) {
    const bool part = it != c.parameters.end() && !it->second.database_part.empty();
    throw InputError("component '" + c.id + "' (" + c.type + "): parameter '" + name +
                         "' has no value for the drive model (simulate, export); " +
                         (part ? "it refers to database part '" + it->second.database_part +
                                     "': resolve it with 'highlift estimate' first, or give a value"
                               : std::string("give a value in the project file")),
                     it != c.parameters.end() && !it->second.where.empty() ? it->second.where : c.where);
  }
  return *it->second.nominal;
}

Scalars Stribeck(const Component& c) {
  Scalars s;
  for (const auto& [param, symbol] : {std::pair<const char*, const char*>{"coulomb_torque", "tau_C"},
                                      {"viscous_coefficient", "d_vis"},
                                      {"stribeck_torque", "tau_S"},
                                      {"stribeck_decay", "f_exp"}}) {
    if (auto v = Value(c, param)) s[symbol] = *v;
  }
  return s;
}

void CheckBacklash(const Component& c) {
  if (ValueOr(c, "backlash", 0.0) > 0 && !Value(c, "stiffness"))
    throw InputError("component '" + c.id + "' (" + c.type + "): a backlash needs a stiffness: give 'stiffness'",
                     c.where);
}

}  // namespace components

const std::vector<ComponentTypeSpec>& ComponentCatalogue() {
  static const std::vector<ComponentTypeSpec> types = {
#define HIGHLIFT_LIST(Name) components::Name##Declaration(),
      HIGHLIFT_COMPONENT_TYPES(HIGHLIFT_LIST)
#undef HIGHLIFT_LIST
  };
  return types;
}

void InstallComponentCatalogue() { highlift::InstallComponentCatalogue(&ComponentCatalogue); }

namespace {
/// Installs the catalogue before main: a static initialiser in the file the linker is told to keep.
const bool kCatalogueInstalled = (InstallComponentCatalogue(), true);
}  // namespace

ComponentRoles ComponentModel::roles() const { return RolesOf(type()); }

PortRatio ComponentModel::SpeedRatioLaw(std::string_view from, std::string_view to) const {
  // A geared flange turns 1/value as fast as "input" (and as every flange that is not geared).
  const ComponentTypeSpec* spec = FindComponentType(type());
  if (!spec) return {};
  auto geared = [&](std::string_view port) -> std::string_view {
    const PortSpec* p = spec->FindPort(port);
    return p ? std::string_view(p->speed_ratio) : std::string_view();
  };
  const std::string_view f = geared(from), t = geared(to);
  if (!t.empty() && f.empty()) return {t, -1};
  if (!f.empty() && t.empty()) return {f, 1};
  return {};
}

double ComponentModel::SpeedRatio(const Component& c, std::string_view from, std::string_view to) const {
  const PortRatio law = SpeedRatioLaw(from, to);
  if (law.parameter.empty() || law.power == 0) return 1.0;
  const double value = components::Require(c, std::string(law.parameter));
  return law.power > 0 ? value : 1.0 / value;
}

ChainMember ComponentModel::Chain(const Component& c, double) const {
  throw InternalError("component '" + c.id + "' (" + c.type + ") is no member of a lumped chain");
}

double ComponentModel::TravelAngle(const Component& c) const {
  throw InputError("component '" + c.id + "' (" + c.type + ") is no actuator: it has no travel", c.where);
}

Sym ComponentModel::InputTravel(const ParameterReader<Sym>&) const { return Sym::Missing("travel of " + std::string(type())); }

const std::vector<const ComponentModel*>& ComponentModels() {
  static const std::vector<const ComponentModel*> models = {
#define HIGHLIFT_LIST(Name) &components::Name##Component(),
      HIGHLIFT_COMPONENT_TYPES(HIGHLIFT_LIST)
#undef HIGHLIFT_LIST
  };
  return models;
}

const ComponentModel* FindComponentModel(std::string_view type) {
  static const std::unordered_map<std::string_view, const ComponentModel*> by_type = [] {
    std::unordered_map<std::string_view, const ComponentModel*> m;
    for (const ComponentModel* model : ComponentModels()) m.emplace(model->type(), model);
    return m;
  }();
  auto it = by_type.find(type);
  return it == by_type.end() ? nullptr : it->second;
}

std::vector<std::string> TypesWithRole(bool ComponentRoles::*role) {
  std::vector<std::string> names;
  for (const ComponentModel* m : ComponentModels())
    if (m->roles().*role) names.emplace_back(m->type());
  return names;
}

}  // namespace highlift::model

/// The symbol model/CMakeLists.txt asks the linker for (-u), so every program linking
/// highlift::model keeps this file and its static initialiser, also from a static library.
extern "C" const bool* highlift_model_component_registry() { return &highlift::model::kCatalogueInstalled; }
