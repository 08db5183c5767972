// Reading and writing JSON project files. Reading is strict: unknown keys are rejected with a
// "did you mean" suggestion, quantities carry units checked against the declared dimension,
// and every error names the file, the JSON pointer, the line and the column.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "highlift/core/project.h"

namespace highlift {

/// Loads and checks a project file (syntax, keys, types, units, ranges; not the graph: see
/// ValidateProject). Throws InputError with file, JSON pointer, line and column.
Project LoadProject(const std::filesystem::path& file);
/// The same from text; `file_name` is used in messages.
Project ParseProject(const std::string& text, const std::string& file_name = "<string>");

/// The project as JSON, in the documented format. Load(Save(p)) == p for every valid project.
nlohmann::json ProjectToJson(const Project& project);
/// Writes atomically (temporary file, then rename), so a failure never leaves half a file.
void SaveProject(const Project& project, const std::filesystem::path& file);

/// Parses a quantity string "50 mm", "[43, 51] GPa", "242 rpm" against `expected`, giving SI.
/// A plain number is taken in SI. Throws InputError (with `where`) on a bad unit or dimension.
Parameter ParseQuantity(const nlohmann::json& value, const Dimension& expected,
                        const SourceLocation& where);

}  // namespace highlift
