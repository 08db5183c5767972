// ExportModelica into a folder: several models share one HighLift package (package.order merged,
// both checkers clean over the whole folder), file names the file system cannot hold are refused
// before anything is written, and a failure while writing leaves the folder as it was.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "common/scratch.h"
#include "export_test_util.h"
#include "highlift/core/error.h"
#include "highlift/core/output_file.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace highlift {
namespace {

namespace fs = std::filesystem;
using testing::ExportTestDir;
using testing::ReadText;

/// A folder for the running test, absent at first; removed when the test passed.
fs::path TempDir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("highlift_folder_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return testing::RemoveAfterTheTest(dir);
}

/// Every file below `dir`, path relative to it, as the checkers take them.
std::vector<GeneratedFile> FolderFiles(const fs::path& dir) {
  std::vector<GeneratedFile> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file())
      files.push_back({fs::relative(entry.path(), dir).generic_string(), ReadText(entry.path())});
  std::sort(files.begin(), files.end(), [](const GeneratedFile& a, const GeneratedFile& b) { return a.path < b.path; });
  return files;
}

std::string Issues(const std::vector<ModelicaIssue>& issues) {
  std::string text;
  for (const auto& issue : issues) text += issue.ToString() + "\n";
  return text;
}

/// The simulator's start, as `highlift export` passes it (--start equilibrium).
void WithSimulatorStart(const Project& project, ModelicaExportOptions& options) {
  options.start = [&project](const model::DriveModel& model) {
    return sim::ComputeStartValues(model.network, sim::DriveModel{model}.Options(project));
  };
}

std::vector<fs::path> Examples() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(HIGHLIFT_SOURCE_DIR) / "examples"))
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Issue 28, item 3 and "Done when": every bundled example, one model each, into one folder,
// alternating the options (tables in the file or inline, full or reduced, equilibrium or rest),
// plus an element network; the folder as a whole passes both checkers and the order lists all.
TEST(ExportFolder, SeveralModelsShareOnePackageAndTheFolderIsComplete) {
  const fs::path dir = TempDir("several");
  std::vector<std::string> names;
  int n = 0;
  std::vector<Project> projects;
  for (const auto& file : Examples()) projects.push_back(LoadProject(file));
  projects.push_back(LoadProject(ExportTestDir() / "friction.json"));
  for (const Project& project : projects) {
    ModelicaExportOptions options;
    options.tables_in_file = n % 2 == 0;
    options.resolution = n % 3 == 1 ? ModelResolution::kReduced : ModelResolution::kFull;
    if (n % 4 != 3) WithSimulatorStart(project, options);
    const ModelicaExportReport report = ExportModelica(project, options, dir);
    names.push_back(report.model_name);
    ++n;
  }
  ASSERT_GE(names.size(), 5u);
  std::string order;
  for (const auto& name : names) order += name + "\n";
  EXPECT_EQ(ReadText(dir / "HighLift" / "Models" / "package.order"), order);
  const auto files = FolderFiles(dir);
  EXPECT_EQ(Issues(CheckModelica(files)), "");
  EXPECT_EQ(Issues(CheckModelicaCompleteness(files)), "");
  // Nothing but the package: no staging folder left behind.
  for (const auto& entry : fs::directory_iterator(dir)) EXPECT_EQ(entry.path().filename(), "HighLift");
}

// A folder written before the order was merged lists only its last model: the next export
// adds the model files it finds, and drops names whose file is gone.
TEST(ExportFolder, TheOrderTakesUnlistedModelFilesAndDropsMissingOnes) {
  const fs::path dir = TempDir("order");
  const Project project = LoadProject(ExportTestDir() / "small_drive.json");
  ModelicaExportOptions options;
  options.model_name = "Alpha";
  ExportModelica(project, options, dir);
  const fs::path order = dir / "HighLift" / "Models" / "package.order";
  testing::WriteText(order, "Gone\n");  // lists a model without a file, and not Alpha
  options.model_name = "Beta";
  const ModelicaExportReport report = ExportModelica(project, options, dir);
  EXPECT_EQ(ReadText(order), "Alpha\nBeta\n");
  EXPECT_EQ(testing::FileOf(report, "HighLift/Models/package.order").content, "Alpha\nBeta\n");
  options.model_name = "Alpha";  // again: listed once
  ExportModelica(project, options, dir);
  EXPECT_EQ(ReadText(order), "Alpha\nBeta\n");
  EXPECT_EQ(Issues(CheckModelica(FolderFiles(dir))), "");
}

// Issue 27, item 13: a model name too long for a file name is refused before anything is
// written (the folder is not even created), naming --model-name.
TEST(ExportFolder, AModelNameTooLongForAFileWritesNothing) {
  const fs::path dir = TempDir("long");
  const Project project = LoadProject(ExportTestDir() / "small_drive.json");
  ModelicaExportOptions options;
  options.model_name = "Rig" + std::string(297, 'x');
  try {
    ExportModelica(project, options, dir);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bytes long, above the file system's limit of 255 bytes"), std::string::npos) << message;
    EXPECT_NE(message.find("give a shorter model name with --model-name"), std::string::npos) << message;
    EXPECT_NE(message.find("nothing was written"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(dir));
}

// Issue 27, item 13: a 300-character project name gives a model name that fits a file name
// (cut at a word), and the export succeeds.
TEST(ExportFolder, AProjectNameOf300CharactersGivesAShortModelName) {
  const fs::path dir = TempDir("longname");
  Project project = LoadProject(ExportTestDir() / "small_drive.json");
  project.name.clear();
  while (project.name.size() < 300) project.name += "flap transmission ";
  project.name.resize(300);
  const ModelicaExportReport report = ExportModelica(project, ModelicaExportOptions{}, dir);
  EXPECT_LE(report.model_name.size(), 80u);
  EXPECT_EQ(report.model_name.rfind("FlapTransmissionFlapTransmission", 0), 0u) << report.model_name;
  EXPECT_EQ(report.model_name.size() % 16, 0u) << report.model_name;  // whole words "FlapTransmission"
  EXPECT_TRUE(fs::exists(dir / report.model_file));
}

/// Exports the model "Before" into `dir`, then "After" with `fail` set up around the call
/// (`fail(true)` before, `fail(false)` after), which must throw; checks that the folder is as
/// "Before" left it and returns the message.
std::string FailedExportMessage(const fs::path& dir, const std::function<void(bool)>& fail) {
  const Project project = LoadProject(ExportTestDir() / "small_drive.json");
  ModelicaExportOptions options;
  options.model_name = "Before";
  ExportModelica(project, options, dir);
  const auto before = FolderFiles(dir);
  options.model_name = "After";
  std::string message;
  fail(true);
  try {
    ExportModelica(project, options, dir);
  } catch (const InputError& e) {
    message = e.what();
  }
  fail(false);
  const auto after = FolderFiles(dir);
  EXPECT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < std::min(after.size(), before.size()); ++i) {
    EXPECT_EQ(after[i].path, before[i].path);
    EXPECT_EQ(after[i].content, before[i].content) << after[i].path;
  }
  return message;
}

// Issue 27, item 13, write all or nothing: a write that fails half way (here the file-size
// limit, as ulimit -f) leaves the earlier export untouched and no staging folder behind.
TEST(ExportFolder, AFailedWriteLeavesTheFolderAsItWas) {
  struct rlimit old_limit;
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  void (*old_handler)(int) = SIG_DFL;
  const std::string message = FailedExportMessage(TempDir("fail"), [&](bool on) {
    if (on) {
      old_handler = std::signal(SIGXFSZ, SIG_IGN);
      struct rlimit small = old_limit;
      small.rlim_cur = 2000;  // bytes: the small files pass, the first larger one fails
      ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    } else {
      ::setrlimit(RLIMIT_FSIZE, &old_limit);
      std::signal(SIGXFSZ, old_handler);
    }
  });
  EXPECT_NE(message.find("cannot write"), std::string::npos) << message;
}

// A signal during the writing (here requested before it starts, as the CLI's handler does while
// the export polls): the files written so far are undone, the folder is as it was.
TEST(ExportFolder, AnInterruptionLeavesTheFolderAsItWas) {
  const std::string message = FailedExportMessage(TempDir("interrupt"), [](bool on) {
    if (on) RequestInterrupt(SIGINT);
    else ClearInterrupt();
  });
  EXPECT_NE(message.find("interrupted by a signal while writing: nothing was written"), std::string::npos) << message;
}

}  // namespace
}  // namespace highlift
