// libFuzzer target: the project reader (strict JSON, keys, units, ranges, the graph) and what
// every command does next with a project it accepted: validate it and write it back as JSON
// (which fails on text that is not UTF-8). Bad input must end in highlift::InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const highlift::Project project = highlift::ParseProject(text, "fuzz.json");
    const highlift::ValidationReport report = highlift::ValidateProject(project);
    (void)report.FullReport();
    (void)highlift::ProjectToJson(project).dump(2);
  } catch (const highlift::InputError&) {
  }
  return 0;
}
