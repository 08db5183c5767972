// Writing the generated files into the output folder: all of them or none, and the package
// order of HighLift.Models merged with the models already in the folder.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <fstream>

#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "writers.h"

namespace highlift::modelica_detail {
namespace {

namespace fs = std::filesystem;

/// The nearest folder of `path` (itself or an ancestor) that exists, for pathconf.
fs::path NearestExisting(fs::path path) {
  std::error_code ec;
  if (path.empty()) path = ".";
  while (!fs::exists(path, ec) && path.has_parent_path() && path.parent_path() != path) path = path.parent_path();
  return fs::exists(path, ec) ? path : fs::path(".");
}

long Limit(const fs::path& folder, int name, long fallback) {
  errno = 0;
  const long value = ::pathconf(folder.c_str(), name);
  return value > 0 ? value : fallback;
}

/// "HighLift/Models/<300 characters>.mo" -> a shortened text for messages.
std::string Shortened(const std::string& text) {
  return text.size() <= 60 ? text : text.substr(0, 40) + "..." + text.substr(text.size() - 12);
}

/// Refuses, before anything is written, file names the file system cannot hold: a name longer
/// than NAME_MAX bytes (255 on Linux) or a path longer than PATH_MAX.
void CheckNameLengths(const std::vector<GeneratedFile>& files, const fs::path& output_dir) {
  const fs::path existing = NearestExisting(output_dir);
  const long name_max = Limit(existing, _PC_NAME_MAX, 255);
  const long path_max = Limit(existing, _PC_PATH_MAX, 4096);
  for (const auto& f : files) {
    for (const auto& part : fs::path(f.path)) {
      const std::string name = part.string();
      if (static_cast<long>(name.size()) <= name_max) continue;
      const bool model = f.path.rfind(std::string(kModelsFolder) + "/", 0) == 0;
      throw InputError("cannot export to '" + output_dir.string() + "': the file name '" + Shortened(name) + "' is " +
                       std::to_string(name.size()) + " bytes long, above the file system's limit of " +
                       std::to_string(name_max) + " bytes" +
                       (model ? "; give a shorter model name with --model-name (at most " +
                                    std::to_string(name_max - 4) + " characters)"
                              : "") +
                       "; nothing was written");
    }
    const std::string full = fs::absolute(output_dir / f.path).string();
    if (static_cast<long>(full.size()) >= path_max)
      throw InputError("cannot export to '" + output_dir.string() + "': the path of '" + Shortened(f.path) + "' is " +
                       std::to_string(full.size()) + " bytes long, at or above the file system's limit of " +
                       std::to_string(path_max) + " bytes; choose a shorter output folder or --model-name; nothing "
                       "was written");
  }
}

std::string Reason(const std::error_code& ec) { return ec.message(); }

/// The folders of `dir` that do not exist yet, outermost first.
std::vector<fs::path> MissingFolders(const fs::path& dir) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p.parent_path() == p) break;
  }
  std::reverse(missing.begin(), missing.end());
  return missing;
}

/// One transaction over the output folder: the folders it created, the files it moved away (to
/// put them back), the files it put in place (to remove them) and its staging folder.
/// Rollback() undoes them in reverse order.
class FolderTransaction {
 public:
  /// Creates `dir` and its missing parents; remembers the ones it created.
  void CreateFolders(const fs::path& dir) {
    for (const auto& p : MissingFolders(dir)) {
      std::error_code ec;
      fs::create_directory(p, ec);
      if (ec)
        throw InputError("cannot create the folder '" + p.string() + "': " + Reason(ec) +
                         "; check that its parent exists and is writable; nothing was written");
      created_.push_back(p);
    }
  }

  /// Moves the staged file `from` to `to`; a file already at `to` is moved to `backup` first.
  void Place(const fs::path& from, const fs::path& to, const fs::path& backup) {
    std::error_code ec;
    if (fs::exists(fs::symlink_status(to, ec))) {
      fs::rename(to, backup, ec);
      if (ec)
        throw InputError("cannot replace '" + to.string() + "': " + Reason(ec) +
                         "; check that the folder is writable; nothing was written");
      moved_.push_back({backup, to});
    }
    fs::rename(from, to, ec);
    if (ec)
      throw InputError("cannot write '" + to.string() + "': " + Reason(ec) +
                       "; check that the folder is writable; nothing was written");
    placed_.push_back(to);
  }

  void Rollback() noexcept {
    std::error_code ec;
    for (auto it = placed_.rbegin(); it != placed_.rend(); ++it) fs::remove(*it, ec);
    for (auto it = moved_.rbegin(); it != moved_.rend(); ++it) fs::rename(it->first, it->second, ec);
    placed_.clear();
    moved_.clear();
  }

  /// Removes the folders it created that are empty now (after a rollback: all of them).
  void RemoveCreatedFolders() noexcept {
    std::error_code ec;
    for (auto it = created_.rbegin(); it != created_.rend(); ++it) fs::remove(*it, ec);  // only when empty
  }

 private:
  std::vector<fs::path> created_;
  std::vector<std::pair<fs::path, fs::path>> moved_;  // backup -> original place
  std::vector<fs::path> placed_;
};

}  // namespace

std::string MergedModelsPackageOrder(const fs::path& output_dir, const std::string& model_name) {
  const fs::path models = output_dir / kModelsFolder;
  std::vector<std::string> names;
  auto has_class = [&](const std::string& name) {
    std::error_code ec;
    return fs::is_regular_file(models / (name + ".mo"), ec);
  };
  auto add = [&](const std::string& name) {
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  };
  // The order written before, without the models whose file is gone.
  std::ifstream in(models / "package.order");
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (has_class(line)) add(line);
  }
  // Model files the order does not list (written by an export that replaced the order).
  std::vector<std::string> unlisted;
  std::error_code ec;
  for (fs::directory_iterator it(models, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path& p = it->path();
    if (p.extension() == ".mo" && p.stem() != "package" && IsModelicaIdentifier(p.stem().string()))
      unlisted.push_back(p.stem().string());
  }
  std::sort(unlisted.begin(), unlisted.end());
  for (const auto& name : unlisted) add(name);
  add(model_name);
  std::string order;
  for (const auto& name : names) order += name + "\n";
  return order;
}

void WriteFilesAllOrNothing(const std::vector<GeneratedFile>& files, const fs::path& output_dir) {
  CheckNameLengths(files, output_dir);
  const fs::path root = output_dir.empty() ? fs::path(".") : output_dir;
  std::error_code ec;
  if (fs::exists(root, ec) && !fs::is_directory(root, ec))
    throw InputError("the output folder '" + root.string() + "' is a file: give a folder (it is created if needed)");
  // Every target must be a file or nothing: a folder in the way fails before anything is written.
  for (const auto& f : files) {
    const fs::path target = root / f.path;
    if (fs::exists(target, ec) && !fs::is_regular_file(target, ec))
      throw InputError("cannot export to '" + root.string() + "': '" + target.string() +
                       "' exists and is no regular file: move it away; nothing was written");
    for (fs::path p = fs::path(f.path).parent_path(); !p.empty(); p = p.parent_path())
      if (fs::exists(root / p, ec) && !fs::is_directory(root / p, ec))
        throw InputError("cannot export to '" + root.string() + "': '" + (root / p).string() +
                         "' is a file where the export needs a folder: move it away; nothing was written");
  }

  // 1. Stage: every file complete (written, synced) in a hidden folder of the output folder (the
  //    same file system, so step 2 only renames). A failure here (disk full, file-size limit)
  //    removes the staging folder: the output folder is as it was.
  // 2. Put every file in place; an old file of the same name goes to the staging folder until
  //    all are in place. A failure puts the old files back and removes the new ones.
  static std::atomic<unsigned> counter{0};
  const fs::path staging = root / (".highlift-export-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  // SIGINT/SIGTERM: the handler only sets a flag while the scope is active; the loops poll it
  // and undo what was done.
  InterruptibleScope interruptible;
  auto stop_if_interrupted = [] {
    if (InterruptRequested())
      throw InputError("interrupted by a signal while writing: nothing was written, the output folder is as it was");
  };
  FolderTransaction transaction;
  try {
    transaction.CreateFolders(staging / "new");
    transaction.CreateFolders(staging / "old");
    for (std::size_t i = 0; i < files.size(); ++i) {
      stop_if_interrupted();
      WriteOutputFile(staging / "new" / std::to_string(i), files[i].content,
                      "Modelica file '" + files[i].path + "'");
    }
    for (std::size_t i = 0; i < files.size(); ++i) {
      stop_if_interrupted();
      const fs::path target = root / files[i].path;
      transaction.CreateFolders(target.parent_path());
      transaction.Place(staging / "new" / std::to_string(i), target, staging / "old" / std::to_string(i));
    }
  } catch (...) {
    transaction.Rollback();
    fs::remove_all(staging, ec);
    transaction.RemoveCreatedFolders();
    throw;
  }
  fs::remove_all(staging, ec);
}

}  // namespace highlift::modelica_detail
