// A structural checker for the Modelica text we generate and for the hand-written HighLift
// library. It is no Modelica compiler; it catches the mistakes a text generator makes:
//
// - every class definition (model, block, package, connector, record, function, type, class)
//   is closed by `end <Name>;` with its own name, in the right nesting;
// - parentheses, brackets and braces are balanced (outside strings and comments);
// - every connect(a, b) joins declared connectors: `inst.port` where `inst` is declared in the
//   class and `port` is a connector of its class, or a connector declared in the class itself;
// - every `Modelica.` name is one of the maintained list of MSL 4.0.0 classes, types, functions
//   and constants (export/src/msl_classes.cc), and every modifier on an MSL class (instance or
//   extends clause) names one of its parameters or variables.
//
// Classes of the HighLift library are known to the checker through the library itself: pass
// the library files as `library` and their connectors (declared or inherited) are collected.
#pragma once

#include <string>
#include <vector>

#include "highlift/export/modelica.h"

namespace highlift {

struct ModelicaIssue {
  std::string file;     ///< path of the checked file
  int line = 0;         ///< 1-based
  std::string message;  ///< what is wrong, naming the class, instance or connector

  std::string ToString() const;  ///< "file:line: message"
};

/// Checks `files` (typically the generated model) against the MSL list and the classes of
/// `library` (the HighLift files, which are checked too when they appear in `files`).
/// Returns every issue found; empty means the text passed.
std::vector<ModelicaIssue> CheckModelica(const std::vector<GeneratedFile>& files,
                                         const std::vector<GeneratedFile>& library = {});

/// The completeness of the models in `files` (read with the classes of `library`), beyond the
/// structure CheckModelica checks:
/// - every parameter of every instance has a value: a modifier, or a default in its class
///   (the MSL parameters without a default are listed in export/src/msl_classes.cc from the
///   4.0.0 sources; the HighLift ones are read from the library text), and a model a user
///   simulates (HighLift.Examples.*, HighLift.Models.*, a top-level model) binds its own;
/// - every conditional connector (`support if useSupport`) that the instance enables is
///   connected, and none that it disables is;
/// - every input connector (Real or Boolean) of an instance is connected.
/// Returns every issue found; empty means complete.
std::vector<ModelicaIssue> CheckModelicaCompleteness(const std::vector<GeneratedFile>& files,
                                                     const std::vector<GeneratedFile>& library = {});

/// True when `path` (e.g. "Modelica.Mechanics.Rotational.Components.Inertia") is in the list of
/// MSL 4.0.0 names the exporter and the library may use.
bool IsKnownMslName(std::string_view path);

/// Parameters and modifiable variables of an MSL class in the list (empty when unknown).
std::vector<std::string> MslModifiers(std::string_view class_path);

/// Connector names of an MSL class in the list (empty when unknown or none).
std::vector<std::string> MslConnectors(std::string_view class_path);

}  // namespace highlift
