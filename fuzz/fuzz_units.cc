// libFuzzer target: unit expressions through UDUNITS-2 (core/src/units.cc) and the conversion
// with a dimension check. Bad units must end in highlift::InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "highlift/core/error.h"
#include "highlift/core/units.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (text.find('\0') != std::string::npos) return 0;  // units come from JSON strings and argv
  try {
    (void)highlift::ParseUnit(text);
    (void)highlift::ToSI(1.5, text, highlift::dimensions::Torque());
  } catch (const highlift::InputError&) {
  }
  return 0;
}
