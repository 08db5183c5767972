// Hydraulic components of the HighLift library.
#include "composites.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {

std::unique_ptr<Element> MakeHydraulicElement(const NetworkElement& element) {
  (void)element;
  return nullptr;
}

std::optional<Composite> ExpandHydraulicComposite(const NetworkElement& element) {
  (void)element;
  return std::nullopt;
}

}  // namespace highlift::sim::detail
