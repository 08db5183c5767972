// Helpers of the campaign tests: the A380-class example, scratch folders, error messages.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "highlift/core/error.h"
#include "highlift/core/project_io.h"

namespace highlift::campaign::testing {

inline const Project& A380() {
  static const Project project = LoadProject(std::string(HIGHLIFT_SOURCE_DIR) + "/examples/a380_class_flaps.json");
  return project;
}

/// A fresh (absent) folder under the build folder's test-campaign/.
inline std::filesystem::path Scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(HIGHLIFT_BINARY_DIR) / "test-campaign" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir.parent_path());
  return dir;
}

/// The message of the InputError `f` throws, or "(no InputError)".
inline std::string MessageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

/// A campaign summary as JSON without its file name (which differs between result folders).
inline nlohmann::json WithoutFile(nlohmann::json summary) {
  summary.erase("file");
  return summary;
}

}  // namespace highlift::campaign::testing
