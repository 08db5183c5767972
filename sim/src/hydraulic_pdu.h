// Internal: the hydraulic power drive unit as a sub-network of hydraulic and mechanical elements.
#pragma once

#include "highlift/sim/network.h"
