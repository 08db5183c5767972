// Drive-system projects (catalogue components) as simulation models.
#pragma once

#include "highlift/sim/network.h"
