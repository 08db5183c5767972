// libFuzzer target: reading a campaign result file (campaign/src/store.cc, summary.cc) and merging
// it (campaign.cc), as `campaign summary`, `campaign merge` and `report --campaign` do. The input
// is SQL, one statement per line, applied to a copy of a small valid result file (made once with
// the store's own schema and checksums): edited keys, values of another type, NULLs, deleted or
// extra rows, dropped tables. Reading must end in a summary or in highlift::InputError (or the
// SQLite wrapper's error for a file SQLite itself refuses); never in another exception or a crash.
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>

#include "../campaign/src/store.h"
#include "highlift/campaign/campaign.h"
#include "highlift/componentdb/sqlite.h"
#include "highlift/core/error.h"

namespace {

namespace fs = std::filesystem;
namespace sqlite = highlift::componentdb::sqlite;

fs::path Folder() {
  static const fs::path folder = [] {
    const fs::path f = fs::temp_directory_path() / ("highlift_fuzz_campaign_" + std::to_string(::getpid()));
    fs::remove_all(f);
    fs::create_directories(f);
    std::atexit([] {
      std::error_code ignored;
      fs::remove_all(fs::temp_directory_path() / ("highlift_fuzz_campaign_" + std::to_string(::getpid())), ignored);
    });
    return f;
  }();
  return folder;
}

/// A complete two-run campaign of two cases and one parameter, as ResultStore writes it.
void WriteTemplate(const fs::path& file) {
  sqlite::Connection c(file, sqlite::Connection::Mode::kReadWriteCreate);
  highlift::campaign::detail::CreateSchema(c);
  c.Execute(R"sql(
    INSERT INTO campaign VALUES('format', '2'), ('campaign_id', '0123456789abcdef'), ('project_name', 'fuzz'),
      ('project_hash', 'fedcba9876543210'), ('model', 'reduced'), ('shard_index', '0'), ('shard_count', '1'),
      ('runs_total', '2'), ('samples_per_case', '1'), ('seed', '1'), ('sampling', 'sobol');
    INSERT INTO cases VALUES(0, 'jam_l1', 'jam', 'gra_l1', 'extend'), (1, 'rupture_shaft_l1', 'rupture', 'shaft_l1', 'retract');
    INSERT INTO parameters VALUES(0, 'pdu.motor_inertia', 3e-4, 2e-4, 4e-4);
    INSERT INTO capacities VALUES('shaft_l1', 'torque capacity', 1500.0);
    INSERT INTO runs VALUES(0, 0, 0, 'nominal', 'ok', '', 812.5, 'shaft_l1', 1.25, 790.0, 4200, 0.5),
                           (1, 1, 0, 'nominal', 'failed', 'solver failure', NULL, NULL, NULL, NULL, 17, 0.1);
    INSERT INTO run_values VALUES(0, 0, 3e-4), (1, 0, 3e-4);
    INSERT INTO component_peaks VALUES(0, 0, 'shaft_l1', -812.5, 1.25), (0, 1, 'gra_l1', 95.0, 1.3);
  )sql");
  for (int run : {0, 1}) {
    sqlite::Statement s(c, "INSERT INTO checksums VALUES(?, ?)");
    s.Bind(1, static_cast<std::int64_t>(run)).Bind(2, highlift::campaign::detail::RunDigest(c, run)).Run();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fs::path template_file = [] {
    const fs::path f = Folder() / "template.sqlite";
    WriteTemplate(f);
    return f;
  }();
  const fs::path dir = Folder() / "case";
  const fs::path out = Folder() / "merged";
  fs::remove_all(dir);
  fs::remove_all(out);
  fs::create_directories(dir);
  const fs::path file = dir / "campaign.sqlite";
  // A signal (libFuzzer's timers) may interrupt the copy (EINTR, a CI run of 2026-12-06): the
  // harness copies again rather than report its own copy as a finding.
  for (std::error_code ec;;) {
    fs::copy_file(template_file, file, fs::copy_options::overwrite_existing, ec);
    if (!ec) break;
    if (ec != std::errc::interrupted) throw fs::filesystem_error("copying the template", template_file, file, ec);
  }
  {
    sqlite::Connection c(file, sqlite::Connection::Mode::kReadWrite);
    std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
    for (std::string line; std::getline(lines, line);) {
      if (line.find('\0') != std::string::npos || line.find("ATTACH") != std::string::npos ||
          line.find("attach") != std::string::npos || line.find("load_extension") != std::string::npos)
        continue;  // only this file is edited
      try {
        c.Execute(line);
      } catch (const sqlite::Error&) {
      }
    }
  }
  try {
    const highlift::campaign::CampaignSummary summary = highlift::campaign::LoadSummary(dir);
    (void)summary.FullReport();
    (void)summary.ToJson().dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
  } catch (const highlift::InputError&) {
  } catch (const sqlite::Error&) {
  }
  try {
    const fs::path merged = highlift::campaign::MergeShards({file}, out);
    (void)highlift::campaign::LoadSummary(merged);
  } catch (const highlift::InputError&) {
  } catch (const sqlite::Error&) {
  }
  return 0;
}
