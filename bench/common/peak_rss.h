// Peak resident memory of a benchmark (Linux): reset the high-water mark before it, read it after.
#pragma once

#include <malloc.h>

#include <fstream>
#include <string>

namespace highlift::bench {

/// Returns freed heap to the system and resets the process's peak resident size (VmHWM) to its
/// current size (Linux >= 4.0), so that PeakRssMB() measures what follows.
inline void ResetPeakRss() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
}

/// The process's peak resident size (VmHWM) in MB.
inline double PeakRssMB() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

}  // namespace highlift::bench
