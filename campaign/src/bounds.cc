#include "highlift/campaign/bounds.h"

#include <cmath>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/text_table.h"
#include "highlift/model/component_model.h"
#include "highlift/reduced_models/analyses.h"

namespace highlift::campaign {
namespace {

double InputSideFactor(const Project& project, const std::string& id) {
  const Component* c = project.FindComponent(id);
  const ComponentTypeSpec* spec = c ? FindComponentType(c->type) : nullptr;
  const model::ComponentModel* m = c ? model::FindComponentModel(c->type) : nullptr;
  if (!spec || !m || m->roles().actuator || !spec->GearedPort() || !spec->FindPort("input")) return 1.0;
  try {
    return m->SpeedRatio(*c, "input", spec->GearedPort()->name);
  } catch (const InputError&) {
    return 1.0;
  }
}

}  // namespace

std::string ComponentBound::Flag() const {
  if (bound()) return "bound";
  return "NOT A BOUND: the simulation exceeds it by " +
         (std::isfinite(exceeded_by) ? FormatNumber(100.0 * exceeded_by, 3) + " %" : std::string("(no single-DOF load)"));
}

std::map<std::string, double> ComponentTorquesAtInput(const Project& project, const std::vector<sim::PeakTorque>& peaks) {
  std::map<std::string, double> out;
  for (const auto& p : peaks) out[p.element] = std::abs(p.tau) * InputSideFactor(project, p.element);
  return out;
}

std::vector<ComponentBound> CompareWithTransient(const reduced_models::PeakReport& report,
                                                 const std::vector<SimulatedCase>& simulated) {
  std::vector<ComponentBound> out;
  for (const auto& w : report.worst) {
    ComponentBound c{w.component, w.local_nominal, w.worst_case, 0.0, std::string(), 0.0};
    for (const auto& t : simulated) {
      auto it = t.components.find(w.component);
      if (t.ok && it != t.components.end() && it->second > c.transient) {
        c.transient = it->second;
        c.transient_case = t.name;
      }
    }
    if (c.transient > c.single_dof * (1.0 + kBoundTolerance))
      c.exceeded_by = c.single_dof > 0 ? c.transient / c.single_dof - 1.0 : INFINITY;
    out.push_back(c);
  }
  return out;
}

}  // namespace highlift::campaign
