// The hydraulic power drive unit as a sub-network of hydraulic and mechanical elements.
#include "hydraulic_pdu.h"
