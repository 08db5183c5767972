// The power drive unit, monitoring and airloads of the HighLift library, as element types.
#include "element_type_builders.h"

namespace highlift::element_types {

void AppendDriveTypes(std::vector<ComponentTypeSpec>& types) { (void)types; }

}  // namespace highlift::element_types
