// libFuzzer target: `highlift db find --where NAME=LO:HI [unit]` (ParseRangeCondition). The text
// before the first newline is the condition, the rest (if any) the component type. Bad input
// must end in highlift::InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "highlift/componentdb/database.h"
#include "highlift/core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  if (text.find('\0') != std::string::npos) return 0;  // argv cannot hold a NUL
  std::string type = "geared_rotary_actuator";
  if (const auto nl = text.find('\n'); nl != std::string::npos) {
    type = text.substr(nl + 1);
    text.resize(nl);
  }
  try {
    (void)highlift::componentdb::ParseRangeCondition(text, type);
  } catch (const highlift::InputError&) {
  }
  return 0;
}
