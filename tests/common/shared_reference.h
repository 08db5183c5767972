// Locates the shared reference material (../shared/reference beside the project root, or
// $HIGHLIFT_SHARED/reference). Tests that need it skip with a clear message where it is absent.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace highlift::testing {

/// The folder `reference/<sub>` of the shared material, or nullopt when it does not exist.
inline std::optional<std::filesystem::path> SharedReference(const std::string& sub) {
  std::filesystem::path base;
  if (const char* env = std::getenv("HIGHLIFT_SHARED"); env != nullptr && *env != '\0') {
    base = std::filesystem::path(env) / "reference";
  } else {
    base = std::filesystem::path(HIGHLIFT_SOURCE_DIR) / ".." / "shared" / "reference";
  }
  std::filesystem::path dir = base / sub;
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) return std::nullopt;
  return std::filesystem::weakly_canonical(dir, ec);
}

}  // namespace highlift::testing

/// Skips the current test with a clear message when the shared reference folder is missing.
#define HIGHLIFT_REQUIRE_SHARED(var, sub)                                                      \
  const auto var##_opt = ::highlift::testing::SharedReference(sub);                            \
  if (!var##_opt) {                                                                            \
    GTEST_SKIP() << "shared reference material 'reference/" << (sub)                           \
                 << "' not found: set HIGHLIFT_SHARED to the folder holding reference/, or "   \
                    "place it at ../shared beside the project root";                           \
  }                                                                                            \
  const std::filesystem::path var = *var##_opt
