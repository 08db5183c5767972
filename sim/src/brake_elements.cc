// Brakes, torque limiters and friction of the HighLift library.
#include "composites.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {

std::unique_ptr<Element> MakeBrakeElement(const NetworkElement& element) {
  (void)element;
  return nullptr;
}

std::optional<Composite> ExpandBrakeComposite(const NetworkElement& element) {
  (void)element;
  return std::nullopt;
}

}  // namespace highlift::sim::detail
