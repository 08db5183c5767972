// `highlift validate PROJECT.json [--json]`: reads the project file strictly and checks the
// component graph. Exit 0 when the project is valid (warnings allowed), 2 when the file cannot be
// read or the graph has errors (invalid input).
#include <iostream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "highlift/core/error.h"
#include "highlift/core/project_io.h"
#include "highlift/core/validate.h"
#include "highlift/sim/drive_network.h"
#include "highlift/sim/simulator.h"

namespace highlift::cli {
namespace {

nlohmann::json IssueJson(const ValidationIssue& issue) {
  return {{"severity", issue.severity == ValidationIssue::Severity::kError ? "error" : "warning"},
          {"component", issue.component},
          {"port", issue.port},
          {"message", issue.message},
          {"location", LocationJson(issue.where)}};
}

/// "component 'x' port 'y': message (file:line:col at /pointer)".
std::string IssueText(const ValidationIssue& issue) {
  std::string s = issue.severity == ValidationIssue::Severity::kError ? "error: " : "warning: ";
  s += issue.message;
  if (!issue.where.empty()) s += " [" + issue.where.ToString() + "]";
  return s;
}

class ValidateCommand : public Command {
 public:
  void Setup(CLI::App& app) override { options_.AddTo(app); }

  int Run() override {
    Project project;
    try {
      project = LoadProject(options_.project);
    } catch (const InputError& e) {
      // With --json the reader's error is the document; the message goes to stderr as well.
      if (options_.json) {
        nlohmann::json doc = {{"file", options_.project},
                              {"ok", false},
                              {"stage", "read"},
                              {"issues", nlohmann::json::array({{{"severity", "error"},
                                                                  {"component", ""},
                                                                  {"port", ""},
                                                                  {"message", e.message()},
                                                                  {"location", LocationJson(e.where())}}})}};
        std::cout << JsonText(doc) << "\n";
      }
      std::cerr << "highlift validate: error: " << e.what() << "\n";  // cleaned by InputError
      return kInvalidInput;
    }

    ValidationReport report = ValidateProject(project);
    // An element network that passes the graph checks gets the simulator's structural check,
    // the one `simulate` applies (undetermined flanges, massless nodes, loops, initial values).
    if (report.ok() && !project.elements.empty() && !sim::IsDriveSystemProject(project)) {
      std::string problem;
      try {
        problem = sim::CheckStructure(sim::NetworkFromProject(project),
                                      project.experiment ? project.experiment->start_time : 0.0);
      } catch (const InputError& e) {
        problem = e.what();
      }
      if (!problem.empty()) report.issues.push_back({ValidationIssue::Severity::kError, "", "", problem, {}});
    }
    std::size_t errors = 0;
    std::size_t warnings = 0;
    for (const auto& issue : report.issues) {
      (issue.severity == ValidationIssue::Severity::kError ? errors : warnings)++;
    }
    const nlohmann::json counts = {{"components", project.components.size()},
                                   {"connections", project.connections.size()},
                                   {"elements", project.elements.size()},
                                   {"element_connections", project.element_connections.size()},
                                   {"requirements", project.requirements.size()},
                                   {"load_cases", project.load_cases.size()},
                                   {"scenarios", project.scenarios.size()}};
    if (options_.json) {
      nlohmann::json issues = nlohmann::json::array();
      for (const auto& issue : report.issues) issues.push_back(IssueJson(issue));
      nlohmann::json doc = {{"file", options_.project},
                            {"name", project.name},
                            {"ok", report.ok()},
                            {"stage", "graph"},
                            {"errors", errors},
                            {"warnings", warnings},
                            {"counts", counts},
                            {"issues", issues}};
      std::cout << JsonText(doc) << "\n";
    }
    for (const auto& issue : report.issues) std::cerr << IssueText(issue) << "\n";
    if (!report.ok()) {
      std::cerr << "highlift validate: " << options_.project << ": " << errors << " error"
                << (errors == 1 ? "" : "s") << " in the component graph; fix the issues above and run "
                << "`highlift validate` again\n";
      return kInvalidInput;
    }
    if (!options_.json) {
      std::cout << "ok: " << options_.project << " (" << project.name << "): "
                << project.components.size() << " components, " << project.connections.size()
                << " connections";
      if (!project.elements.empty()) {
        std::cout << ", " << project.elements.size() << " elements, "
                  << project.element_connections.size() << " element connections";
      }
      std::cout << ", " << project.requirements.size() << " requirements, "
                << project.load_cases.size() << " load cases, " << project.scenarios.size()
                << " scenarios";
      if (warnings > 0) std::cout << ", " << warnings << " warning" << (warnings == 1 ? "" : "s");
      std::cout << "\n";
    }
    return kSuccess;
  }

 private:
  CommonOptions options_;
};

}  // namespace

HIGHLIFT_REGISTER_COMMAND(ValidateCommand, "validate",
                          "Check a project file: syntax, keys, units, ranges and the component graph")

}  // namespace highlift::cli
