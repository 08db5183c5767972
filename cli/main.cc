// highlift: the command-line front end. Commands register themselves (cli/command.h).
#include <iostream>
#include <map>

#include "command.h"
#include "highlift/core/error.h"

namespace highlift::cli {

std::vector<CommandEntry>& Commands() {
  static std::vector<CommandEntry> commands;
  return commands;
}

void CommonOptions::AddTo(CLI::App& app, bool project_required) {
  auto* opt = app.add_option("project", project, "JSON project file");
  if (project_required) opt->required();
  app.add_flag("--json", json, "Print one JSON document on stdout instead of tables");
  app.add_option("--db", db, "Component database (default: the shipped database in the user's data directory)");
}

}  // namespace highlift::cli

int main(int argc, char** argv) {
  using namespace highlift::cli;
  CLI::App app{"highlift: design-tool backend for aircraft high-lift drive systems"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("highlift ") + HIGHLIFT_VERSION);

  std::map<CLI::App*, std::unique_ptr<Command>> commands;
  for (const auto& entry : Commands()) {
    CLI::App* sub = app.add_subcommand(entry.name, entry.description);
    auto command = entry.make();
    command->Setup(*sub);
    commands.emplace(sub, std::move(command));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the usage problem to stderr
    return kInvalidInput;
  }

  for (auto& [sub, command] : commands) {
    if (!sub->parsed()) continue;
    try {
      return command->Run();
    } catch (const highlift::InputError& e) {
      std::cerr << "highlift " << sub->get_name() << ": error: " << e.what() << "\n";
      return kInvalidInput;
    } catch (const highlift::InternalError& e) {
      std::cerr << "highlift " << sub->get_name() << ": " << e.what() << "\n";
      return 3;
    } catch (const std::exception& e) {
      std::cerr << "highlift " << sub->get_name() << ": error: " << e.what() << "\n";
      return kInvalidInput;
    }
  }
  return kInvalidInput;
}
