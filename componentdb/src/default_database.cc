// The default database in the user's data directory, created from the seed compiled into the
// library (seed_data.cc is generated from data/components.csv at build time, so an installed
// or relocated program never needs to find the data folder).
#include <unistd.h>

#include <cstdlib>
#include <cerrno>
#include <cstring>
#include <random>
#include <vector>

#include "highlift/componentdb/database.h"
#include "highlift/componentdb/io.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"

namespace highlift::componentdb {

namespace detail {
extern const char* const kSeedCsv;  // generated: seed_data.cc
}

std::filesystem::path UserDataDirectory() {
  const auto env = [](const char* name) -> std::string {
    const char* v = std::getenv(name);
    return v ? std::string(v) : std::string();
  };
  if (const auto dir = env("HIGHLIFT_DATA_DIR"); !dir.empty()) return dir;
  if (const auto xdg = env("XDG_DATA_HOME"); !xdg.empty()) return std::filesystem::path(xdg) / "highlift";
  if (const auto home = env("HOME"); !home.empty())
    return std::filesystem::path(home) / ".local" / "share" / "highlift";
  throw InputError("cannot find the user's data directory: neither HIGHLIFT_DATA_DIR, XDG_DATA_HOME nor HOME is set; set HIGHLIFT_DATA_DIR or pass --db PATH");
}

std::filesystem::path DefaultDatabasePath() { return UserDataDirectory() / "components.sqlite"; }

const std::string& SeedCsv() {
  static const std::string seed(detail::kSeedCsv);
  return seed;
}

Records SeedRecords() {
  Records r = ParseCsv(SeedCsv(), "data/components.csv");
  ValidateRecords(r);
  return r;
}

std::vector<std::string> DifferencesFromSeed(const ComponentDatabase& db) {
  const Records seed = SeedRecords();
  std::vector<std::string> out;
  for (const Part& part : seed.parts) {
    const std::optional<Part> held = db.FindPart(part.designation);
    if (!held || !(*held == part)) out.push_back(part.designation);
  }
  for (const Material& material : seed.materials) {
    const std::optional<Material> held = db.FindMaterial(material.name);
    if (!held || !(*held == material)) out.push_back(material.name);
  }
  return out;
}

namespace {

/// Builds the seed database under a temporary name and links it into place unless `file`
/// appeared meanwhile (another process won the race; its database is kept).
void BuildFromSeed(const std::filesystem::path& file) {
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  if (ec)
    throw InputError("cannot create the directory '" + file.parent_path().string() + "' for the component database: " +
                     ec.message() + "; set HIGHLIFT_DATA_DIR to a writable directory or pass --db PATH");
  std::random_device random;
  const auto tmp = std::filesystem::path(file.string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                                         std::to_string(random()));
  // A SIGINT or SIGTERM during the build removes these (the CLI's handler), so an interrupted
  // first creation leaves no components.sqlite.tmp-* behind.
  std::vector<int> slots;
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) slots.push_back(RegisterTemporaryFile(tmp.string() + suffix));
  const auto remove_tmp = [&] {
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::filesystem::remove(tmp.string() + suffix, ec);
    for (int slot : slots) UnregisterTemporaryFile(slot);
  };
  try {
    {
      auto db = ComponentDatabase::Open(tmp, ComponentDatabase::Mode::kCreate);
      db.Import(SeedRecords());
    }  // closing the last connection checkpoints the WAL into the file and removes it
    // rename() over an existing file would replace a database another process just created;
    // link() fails instead, so the first one wins and later ones keep it.
    if (::link(tmp.c_str(), file.c_str()) != 0 && errno != EEXIST)
      throw InputError("cannot create the component database '" + file.string() + "': " +
                       std::strerror(errno) + "; set HIGHLIFT_DATA_DIR to a writable directory or pass --db PATH");
    remove_tmp();
  } catch (...) {
    remove_tmp();
    throw;
  }
}

}  // namespace

void CreateDatabaseFromSeed(const std::filesystem::path& file) {
  if (std::filesystem::exists(file))
    throw InputError("cannot create the component database '" + file.string() + "': the file exists; remove it first or choose another path");
  BuildFromSeed(file);
}

ComponentDatabase OpenDatabase(const std::string& path, ComponentDatabase::Mode mode) {
  if (!path.empty()) return ComponentDatabase::Open(path, mode);
  const auto file = DefaultDatabasePath();
  if (!std::filesystem::exists(file)) BuildFromSeed(file);
  return ComponentDatabase::Open(file, mode == ComponentDatabase::Mode::kReadOnly ? mode
                                                                                  : ComponentDatabase::Mode::kReadWrite);
}

}  // namespace highlift::componentdb
