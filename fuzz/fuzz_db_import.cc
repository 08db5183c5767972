// libFuzzer target: the component database import formats (CSV and JSON, componentdb/src/io.cc)
// and the export of what they accepted (JSON output fails on text that is not UTF-8). The first
// byte chooses the format. Bad input must end in highlift::InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "highlift/componentdb/io.h"
#include "highlift/core/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool csv = data[0] == 'c' || data[0] == 't';  // "type,..." header: seeds are the files themselves
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    highlift::componentdb::Records records = csv ? highlift::componentdb::ParseCsv(text, "fuzz.csv")
                                                 : highlift::componentdb::ParseJson(text, "fuzz.json");
    highlift::componentdb::ValidateRecords(records);
    (void)highlift::componentdb::ToJson(records).dump(2);
    (void)highlift::componentdb::ToCsv(records);
  } catch (const highlift::InputError&) {
  }
  return 0;
}
