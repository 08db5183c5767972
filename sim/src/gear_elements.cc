// Gears and failure elements of the HighLift library.
#include "composites.h"
#include "model.h"
#include "msl_elements.h"

namespace highlift::sim::detail {

std::unique_ptr<Element> MakeGearElement(const NetworkElement& element) {
  (void)element;
  return nullptr;
}

std::optional<Composite> ExpandGearComposite(const NetworkElement& element) {
  (void)element;
  return std::nullopt;
}

}  // namespace highlift::sim::detail
