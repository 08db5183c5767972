// Brakes, torque limiters and friction of the HighLift library.
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {

std::unique_ptr<Element> MakeBrakeElement(const NetworkElement& element) {
  (void)element;
  return nullptr;
}

}  // namespace highlift::sim::detail
