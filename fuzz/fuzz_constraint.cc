// libFuzzer target: the constraint language of requirements (icsp/src/parser.cc), with the
// dimension checks of requirements on. Bad text must end in highlift::InputError, never a
// crash (deep nesting, division by zero, odd units).
#include <cstddef>
#include <cstdint>
#include <string>

#include "highlift/core/error.h"
#include "highlift/icsp/network.h"
#include "highlift/icsp/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  using highlift::icsp::Interval;
  highlift::icsp::Network net;
  net.AddVariable("pdu.max_output_torque", Interval(100.0, 900.0), "N*m");
  net.AddVariable("shaft_1.length", Interval(1.0, 4.0), "m");
  net.AddVariable("gra_1.ratio", Interval(100.0, 250.0), "");
  net.AddVariable("x", Interval(-1.0, 1.0));
  try {
    highlift::icsp::ParseConstraint(net, text, "requirement 'fuzz'", {}, {}, true);
  } catch (const highlift::InputError&) {
  }
  return 0;
}
