// Helpers of the export tests: files, golden comparison, structural check of generated text.
// Set HIGHLIFT_UPDATE_GOLDEN=1 to rewrite the golden files from the current output (then
// review the diff before committing).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "highlift/core/project_io.h"
#include "highlift/export/modelica.h"
#include "highlift/export/modelica_check.h"

namespace highlift::testing {

inline std::filesystem::path ExportTestDir() {
  return std::filesystem::path(HIGHLIFT_SOURCE_DIR) / "tests" / "export";
}

inline std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void WriteText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// Compares `text` with tests/export/golden/<name>; rewrites it with HIGHLIFT_UPDATE_GOLDEN=1.
inline void ExpectGolden(const std::string& name, const std::string& text) {
  const auto path = ExportTestDir() / "golden" / name;
  const char* update = std::getenv("HIGHLIFT_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    std::ofstream(path, std::ios::binary) << text;
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(path))
      << "golden file " << path << " is missing: run the test with HIGHLIFT_UPDATE_GOLDEN=1";
  const std::string golden = ReadText(path);
  if (golden == text) return;
  // Report the first differing line.
  std::istringstream a(golden), b(text);
  std::string la, lb;
  int line = 0;
  while (true) {
    ++line;
    const bool ga = static_cast<bool>(std::getline(a, la));
    const bool gb = static_cast<bool>(std::getline(b, lb));
    if (!ga && !gb) break;
    if (la != lb || ga != gb) {
      ADD_FAILURE() << "output differs from golden file " << path << " at line " << line
                    << "\n  golden: " << la << "\n  output: " << lb
                    << "\n(if the change is intended, rerun with HIGHLIFT_UPDATE_GOLDEN=1)";
      return;
    }
  }
  ADD_FAILURE() << "output differs from golden file " << path;
}

/// The generated file named `path` in a report.
inline const GeneratedFile& FileOf(const ModelicaExportReport& report, const std::string& path) {
  for (const auto& f : report.files)
    if (f.path == path) return f;
  throw std::runtime_error("no generated file " + path);
}

/// The model text with wrapped modifier lists joined onto one line, for searching.
inline std::string Flatten(std::string text) {
  for (const std::string& from : {std::string("(\n    "), std::string(",\n    ")}) {
    const std::string to = from[0] == '(' ? "(" : ", ";
    for (auto pos = text.find(from); pos != std::string::npos; pos = text.find(from, pos))
      text.replace(pos, from.size(), to);
  }
  return text;
}

/// All issues of the structural check of every .mo file of the report, one per line.
inline std::string CheckIssues(const ModelicaExportReport& report) {
  std::string text;
  for (const auto& issue : CheckModelica(report.files)) text += issue.ToString() + "\n";
  return text;
}

/// The model file of the project's export at `resolution` in `scenario`; a structural issue of
/// any generated file is a test failure.
inline std::string ExportedModelText(const Project& project, ModelResolution resolution, const std::string& scenario) {
  ModelicaExportOptions options;
  options.resolution = resolution;
  options.scenario = scenario;
  const ModelicaExportReport report = GenerateModelica(project, options);
  EXPECT_EQ(CheckIssues(report), "") << scenario << " " << ToString(resolution);
  return FileOf(report, report.model_file).content;
}

}  // namespace highlift::testing
