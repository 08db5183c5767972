// position_sensor: an angle sensor on the transmission (its rotor an Inertia, ports a and b).
// A tip sensor (APPU, any role but "fppu") feeds the failure monitor, whose thresholds are its
// parameters (or the catalogue defaults of this type without one).
#include "component_util.h"
#include "highlift/core/catalogue.h"

namespace highlift::model::components {
namespace {

constexpr const char* kType = "position_sensor";

class PositionSensorModel final : public NamedModel {
 public:
  PositionSensorModel() : NamedModel(kType) {}

  void Expand(const Component& c, ExpansionContext& x) const override {
    x.Add("Inertia", c.id, {{"J", Require(c, "inertia")}}, c.id);
    MapAB(c, x);
    auto role = c.texts.find("role");
    if (role == c.texts.end() || role->second != "fppu") x.AddTipSensor(c);
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(PositionSensor, PositionSensorModel)

namespace highlift::model {

MonitorThresholds MonitorSettings(const Component* tip_sensor) {
  auto value = [&](const std::string& name) {
    if (tip_sensor) return components::Require(*tip_sensor, name);
    const ComponentTypeSpec* spec = FindComponentType(components::kType);
    const ParameterSpec* p = spec ? spec->FindParameter(name) : nullptr;
    HIGHLIFT_CHECK(p && p->nominal, std::string("catalogue: ") + components::kType + "." + name + " has no default");
    return *p->nominal;
  };
  return {value("asymmetry_threshold"), value("overspeed_factor"), value("latency")};
}

}  // namespace highlift::model
