// Builds the text of one Modelica model: instances with modifiers, connect() statements with
// line annotations, a deterministic diagram layout, an experiment annotation and
// documentation. Used by the element-network and the drive-system writers.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace highlift::modelica_detail {

/// One modifier: `name=value` or, with a nested modification, `name(start=0, fixed=true)`.
struct Modifier {
  std::string name;
  std::string value;  ///< "=" part (empty when `nested` is used)
  std::vector<std::pair<std::string, std::string>> nested;  ///< name(a=b, ...)
};

struct Instance {
  std::string class_path;  ///< "Modelica.Mechanics.Rotational.Components.Inertia"
  std::string name;        ///< Modelica identifier
  std::vector<Modifier> modifiers;
  std::string comment;     ///< description string (escaped on output)
};

struct Experiment {
  double stop_time = 1.0;
  double tolerance = 1e-6;
  double interval = 1e-3;
};

class ModelWriter {
 public:
  explicit ModelWriter(std::string name) : name_(std::move(name)) {}

  void AddInstance(Instance instance);
  /// connect(a, b); `a` and `b` are "instance.connector" or a connector of the model itself.
  void AddConnect(std::string a, std::string b);
  /// A parameter of the model: `parameter <type> <name> = <value> "comment";`
  void AddParameter(std::string type, std::string name, std::string value, std::string comment);
  /// An equation written into the equation section after the connects.
  void AddEquation(std::string equation);
  /// An equation of the initial equation section, e.g. "der(spring.phi_rel) = 0;".
  void AddInitialEquation(std::string equation);
  void SetExperiment(Experiment experiment) { experiment_ = experiment; }
  void SetDescription(std::string description) { description_ = std::move(description); }
  /// The enclosing package: Render() starts with `within <package>;` (empty: a top-level class).
  void SetWithin(std::string package) { within_ = std::move(package); }
  /// HTML body of the Documentation(info=...) annotation (escaped on output).
  void SetDocumentation(std::string html) { documentation_ = std::move(html); }

  bool HasInstance(const std::string& name) const;
  int instance_count() const { return static_cast<int>(instances_.size()); }
  int connect_count() const { return static_cast<int>(connects_.size()); }

  /// The complete model text.
  std::string Render() const;

 private:
  struct Position {
    int x = 0;
    int y = 0;
  };
  std::map<std::string, Position> Layout() const;

  std::string name_;
  std::string within_;
  std::string description_;
  std::string documentation_;
  std::vector<Instance> instances_;
  std::vector<std::pair<std::string, std::string>> connects_;
  std::vector<std::string> parameters_;
  std::vector<std::string> equations_;
  std::vector<std::string> initial_equations_;
  std::optional<Experiment> experiment_;
};

/// `[1, 2; 3, 4]` for a matrix (rows of equal length), numbers by FormatModelicaReal.
std::string FormatMatrix(const std::vector<std::vector<double>>& rows, const std::string& what);

}  // namespace highlift::modelica_detail
