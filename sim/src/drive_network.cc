// Drive-system projects (catalogue components) as simulation models.
#include "highlift/sim/drive_network.h"
