// Hydraulic components of the HighLift library.
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {

std::unique_ptr<Element> MakeHydraulicElement(const NetworkElement& element) {
  (void)element;
  return nullptr;
}

}  // namespace highlift::sim::detail
