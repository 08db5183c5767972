// jam: a jam element on a flange (port a), tying it to the structure at the scenario's time;
// one HighLift.Mechanical.Jam.
#include "component_util.h"

namespace highlift::model::components {
namespace {

class JamModel final : public NamedModel {
 public:
  JamModel() : NamedModel("jam") {}

  std::vector<std::string> PowerPorts() const override { return {}; }

  /// A jam stands for the structure: no inertia, no stiffness in the lumped models.
  template <class T>
  Lumped<T> Law(const ParameterReader<T>&) const {
    return {};
  }
  HIGHLIFT_LUMPED_LAW

  void Expand(const Component& c, ExpansionContext& x) const override {
    const double stiffness = Require(c, "stiffness");
    Scalars s = {{"c", stiffness}, {"d", x.beta() * stiffness}};
    if (const Scenario* scenario = x.scenario(); scenario && scenario->jam_component == c.id)
      s["t_jam"] = *scenario->jam_time;
    x.Add("Jam", c.id, s, c.id);
    x.MapPort(c, "a", c.id + ".flange");
  }
};

}  // namespace
}  // namespace highlift::model::components

HIGHLIFT_REGISTER_COMPONENT(Jam, JamModel)
