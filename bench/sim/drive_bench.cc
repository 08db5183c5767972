// Benchmarks of the drive-system scenarios (sim/src/drive_network.cc).
#include <benchmark/benchmark.h>
