// The hydraulic PDU sub-network moved to the model layer (highlift/model/hydraulic_pdu.h); these
// names keep the simulator's tests working.
#pragma once

#include "highlift/model/hydraulic_pdu.h"

namespace highlift::sim::detail {

using model::detail::AddHydraulicPdu;
using model::detail::IsHydraulicPdu;
using model::detail::PduPorts;

}  // namespace highlift::sim::detail
