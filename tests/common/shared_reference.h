// Locates the shared reference material: $HIGHLIFT_SHARED/reference when HIGHLIFT_SHARED is set,
// else ../shared/reference beside the project root. Tests that need it skip with a message that
// names the paths looked at where it is absent.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace highlift::testing {

/// Where `reference/<sub>` was looked for, and whether it was found.
struct SharedReferenceLookup {
  std::optional<std::filesystem::path> dir;  ///< the folder, canonical; nullopt when absent
  std::string message;                       ///< when absent: the paths looked at and the remedy
};

/// Looks for the folder `reference/<sub>` of the shared material.
inline SharedReferenceLookup LocateSharedReference(const std::string& sub) {
  const std::filesystem::path beside_root =
      (std::filesystem::path(HIGHLIFT_SOURCE_DIR) / ".." / "shared" / "reference" / sub).lexically_normal();
  const std::string what = "shared reference material 'reference/" + sub + "' not found: ";
  const std::string remedy = "; set HIGHLIFT_SHARED to the folder holding reference/, or place that folder at "
                             "../shared beside the project root";
  SharedReferenceLookup out;
  std::filesystem::path dir;
  if (const char* env = std::getenv("HIGHLIFT_SHARED"); env != nullptr && *env != '\0') {
    dir = (std::filesystem::path(env) / "reference" / sub).lexically_normal();
    out.message = what + "$HIGHLIFT_SHARED/reference/" + sub + " (" + dir.string() +
                  ") does not exist; HIGHLIFT_SHARED is set, so ../shared/reference/" + sub +
                  " beside the project root (" + beside_root.string() + ") was not looked at" + remedy +
                  " and unset HIGHLIFT_SHARED";
  } else {
    dir = beside_root;
    out.message = what + "HIGHLIFT_SHARED is not set (so no $HIGHLIFT_SHARED/reference/" + sub +
                  "), and ../shared/reference/" + sub + " beside the project root (" + beside_root.string() +
                  ") does not exist" + remedy;
  }
  std::error_code ec;
  if (std::filesystem::exists(dir, ec)) {
    out.dir = std::filesystem::weakly_canonical(dir, ec);
    out.message.clear();
  }
  return out;
}

/// The folder `reference/<sub>` of the shared material, or nullopt when it does not exist.
inline std::optional<std::filesystem::path> SharedReference(const std::string& sub) {
  return LocateSharedReference(sub).dir;
}

}  // namespace highlift::testing

/// Skips the current test, naming the paths looked at, when the shared reference folder is missing.
#define HIGHLIFT_REQUIRE_SHARED(var, sub)                                       \
  const auto var##_lookup = ::highlift::testing::LocateSharedReference(sub);    \
  if (!var##_lookup.dir) {                                                      \
    GTEST_SKIP() << var##_lookup.message;                                       \
  }                                                                             \
  const std::filesystem::path var = *var##_lookup.dir
