// Modelica export: writes the hand-written HighLift Modelica library and a model of a project
// (Modelica 3.x text on top of the Modelica Standard Library 4.0.0). The model is a class of
// the package HighLift.Models, so the output folder holds one top-level class: a tool loads
// HighLift/package.mo and simulates HighLift.Models.<name>.
//
// - An element network ("elements"/"element_connections") becomes a model that uses the MSL
//   classes directly, with the project's instance names and parameters, so that a Modelica tool
//   reproduces the MSL reference results.
// - A drive-system project ("components"/"connections") becomes a model built from HighLift and
//   MSL components: full resolution (each shaft split into settings.shaft_elements elements, at
//   least 4) or reduced (inertias lumped at gearboxes and stations), driven by a scenario's load
//   case. The translation is the simulator's (sim::BuildDriveNetwork): the same elements,
//   parameter values and connections.
//
// Output is deterministic: the same project and options give byte-identical files.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "highlift/core/project.h"
#include "highlift/model/drive_network.h"
#include "highlift/model/start_values.h"

namespace highlift {

/// Resolution of a drive-system model.
enum class ModelResolution {
  kFull,     ///< every shaft segment split into settings.shaft_elements (>= 4) spring-inertia elements
  kReduced,  ///< inertias lumped at gearboxes and stations, one spring per segment
};

/// "full", "reduced".
std::string ToString(ModelResolution resolution);
/// Inverse of ToString; throws InputError naming the valid values.
ModelResolution ModelResolutionFromString(std::string_view name);

struct ModelicaExportOptions {
  ModelResolution resolution = ModelResolution::kFull;  // drive-system models only
  std::string scenario;             // scenario driving the model; empty: the first one, if any
  std::string model_name;           // Modelica name of the model; empty: from the project name
  bool tables_in_file = false;      // scenario tables in <model>.txt read by CombiTimeTable
                                    // (else inline `table=[...]`)
  /// Drive systems: the start of the model, computed from the very element network the export
  /// writes. `highlift export` passes the simulator's start (sim::ComputeStartValues: static
  /// equilibrium of the loads held by the parked brakes), written as fixed start values and
  /// initial equations. Empty: no start values (the model starts at rest, springs untwisted,
  /// as the classes' defaults; `highlift export --start rest`). Element networks carry their
  /// own start values (the project's phi_start, w_start, ...) and ignore it.
  std::function<model::StartValues(const model::DriveModel&)> start;

  /// Throws InputError when an option is invalid (e.g. a model name that is no identifier).
  void Validate() const;
};

/// One generated text file, path relative to the output folder ("HighLift/package.mo").
struct GeneratedFile {
  std::string path;
  std::string content;
};

/// What the export produced.
struct ModelicaExportReport {
  std::string model_name;              ///< Modelica name of the project model
  std::string model_path;              ///< its full name, "HighLift.Models.<model_name>"
  std::string model_file;              ///< its path relative to the output folder
                                       ///< ("HighLift/Models/<model_name>.mo")
  std::string start;                   ///< the start written ("rest", or how it was found)
  std::string kind;                    ///< "element network" or "drive system"
  std::string scenario;                ///< scenario used (empty for element networks / none)
  std::vector<GeneratedFile> files;    ///< every file written, in path order
  std::map<std::string, std::string> renamed;  ///< project id -> Modelica name, where they differ
  int component_count = 0;             ///< instances declared in the model
  int connection_count = 0;            ///< connect() statements in the model

  std::string BriefReport() const;
};

/// The HighLift library exactly as shipped (one class per file, package.mo/package.order),
/// with paths such as "HighLift/Mechanical/ShaftBrake.mo", in path order.
std::vector<GeneratedFile> HighLiftLibraryFiles();

/// Generates the HighLift library and the project model in memory (nothing is written).
/// Throws InputError for a project that cannot be exported (no elements and no components, an
/// unknown element type, an unknown scenario, a parameter without a value, ...).
ModelicaExportReport GenerateModelica(const Project& project, const ModelicaExportOptions& options);

/// GenerateModelica, then writes every file below `output_dir` (created if needed): all of them
/// or none. File names the file system cannot hold are refused before anything is written
/// (InputError naming --model-name); the files are written completely into a staging folder of
/// `output_dir` and then renamed into place, and a failure on the way puts the old files back.
/// HighLift/Models/package.order lists the models already in the folder and this one (so
/// several exports share one folder); the report's copy of it is the merged one.
ModelicaExportReport ExportModelica(const Project& project, const ModelicaExportOptions& options,
                                    const std::filesystem::path& output_dir);

// ---- Modelica text helpers (public because the CLI and the tests use them) --------------------

/// True when `name` is a Modelica 3.x keyword (`model`, `end`, `der`, `time`-like reserved words
/// of the grammar: algorithm, and, annotation, ..., within).
bool IsModelicaKeyword(std::string_view name);

/// True when `name` is a keyword or the name of a predefined type or built-in package of the
/// language (Real, Integer, Boolean, String, Clock, StateSelect, ExternalObject, AssertionLevel,
/// Connections): no instance or model may be named so.
bool IsModelicaReservedName(std::string_view name);

/// True when `name` is a valid (non-quoted) Modelica identifier that is no reserved name.
bool IsModelicaIdentifier(std::string_view name);

/// UTF-8 text with the Latin letters that carry diacritics, and the ligatures, as their ASCII
/// letters ("Ünïcödé" -> "Unicode", "ß" -> "ss", "Æ" -> "AE"); every other non-ASCII character
/// (and every byte that is no UTF-8) becomes '_'.
std::string TransliterateToAscii(std::string_view text);

/// A valid Modelica identifier for `name`: transliterated (TransliterateToAscii), characters
/// outside [A-Za-z0-9_] become '_', a leading digit or an empty name gets the prefix "x_", a
/// reserved name (keyword, predefined type) gets the suffix "_".
/// "shaft-l1" -> "shaft_l1", "1st" -> "x_1st", "end" -> "end_", "Real" -> "Real_", "étage" -> "etage".
std::string SanitizeModelicaIdentifier(std::string_view name);

/// Assigns unique sanitised identifiers to project names, in insertion order: the first name
/// that sanitises to "a_b" keeps it, a later one gets "a_b_2", "a_b_3", ... Reserved names (used
/// by the generator itself) are never handed out.
class IdentifierMap {
 public:
  explicit IdentifierMap(std::vector<std::string> reserved = {});
  /// The identifier for `name` (the same on every call for the same name).
  const std::string& Add(const std::string& name);
  /// The identifier of a name added before; throws InternalError otherwise.
  const std::string& Get(const std::string& name) const;
  bool Contains(const std::string& name) const;
  /// Names whose identifier differs from the name, name -> identifier.
  std::map<std::string, std::string> Renamed() const;

 private:
  std::map<std::string, std::string> by_name_;
  std::map<std::string, std::string> taken_;  // identifier -> name ("" for reserved)
};

/// `text` as the body of a Modelica string literal (the quotes are not added): backslash and
/// double quote are escaped, and so are the control characters Modelica has escapes for
/// (\a \b \f \n \r \t \v); other control characters are dropped.
std::string EscapeModelicaString(std::string_view text);

/// A Modelica real literal for a finite value: the shortest text that reads back to the same
/// double ("0.1", "10000", "1e-06", "-2.5"), or the 15-digit text when that reads back within
/// 2 units in the last place (0.034999999999999996 -> "0.035": the noise of arithmetic on
/// decimal data). Throws InputError for inf/nan naming `what`.
std::string FormatModelicaReal(double value, std::string_view what = "value");

}  // namespace highlift
