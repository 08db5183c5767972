// The element network moved to the model layer (highlift/model/network.h), below both the
// simulator and the Modelica export. These names keep the simulator's callers working.
#pragma once

#include "highlift/model/network.h"

namespace highlift::sim {

using model::ElementParameters;
using model::Network;
using model::NetworkConnection;
using model::NetworkElement;
using model::NetworkFromProject;

}  // namespace highlift::sim
