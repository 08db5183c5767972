// Gears and failure elements of the HighLift library, as element types.
#include "element_type_builders.h"

namespace highlift::element_types {

void AppendGearTypes(std::vector<ComponentTypeSpec>& types) { (void)types; }

}  // namespace highlift::element_types
