// Brakes, torque limiters and friction of the HighLift library, as element types.
#include "element_type_builders.h"

namespace highlift::element_types {

void AppendBrakeTypes(std::vector<ComponentTypeSpec>& types) { (void)types; }

}  // namespace highlift::element_types
