// Reads a generated model back for the comparisons with the simulator's networks: its
// declarations (class, modifiers by name) and its connect() statements, plus a union-find over
// "instance.port" names so that two models can be compared by which ports share a node.
#pragma once

#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "export_test_util.h"

namespace highlift::testing {

struct ExportedInstance {
  std::string class_path;
  std::map<std::string, std::string> modifiers;  ///< name -> value text as written
};

struct ExportedModel {
  std::map<std::string, ExportedInstance> instances;
  std::vector<std::pair<std::string, std::string>> connects;  ///< "instance.port" ([1] dropped)
};

/// The top-level `name=value` pairs of a modifier list (commas inside brackets do not split).
inline std::map<std::string, std::string> SplitModifiers(const std::string& text) {
  std::map<std::string, std::string> out;
  int depth = 0;
  std::string item;
  auto flush = [&] {
    const auto eq = item.find('=');
    if (eq != std::string::npos) {
      std::string name = item.substr(0, eq), value = item.substr(eq + 1);
      auto trim = [](std::string& s) {
        s.erase(0, s.find_first_not_of(' '));
        s.erase(s.find_last_not_of(' ') + 1);
      };
      trim(name);
      trim(value);
      out[name] = value;
    }
    item.clear();
  };
  for (char c : text) {
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (c == ',' && depth == 0) {
      flush();
      continue;
    }
    item += c;
  }
  flush();
  return out;
}

/// Parses a model written by highlift export (flattened first, so that every declaration is
/// one line "  Class name(modifiers)").
inline ExportedModel ParseExportedModel(const std::string& model_text) {
  const std::string text = Flatten(model_text);
  ExportedModel model;
  const auto equations = text.find("\nequation\n");
  const std::regex declaration(R"(^  ([A-Za-z][A-Za-z0-9_.]*) ([A-Za-z_][A-Za-z0-9_]*)(\((.*)\))?$)");
  std::istringstream lines(text.substr(0, equations));
  std::smatch m;
  for (std::string line; std::getline(lines, line);)
    if (std::regex_match(line, m, declaration)) model.instances[m[2]] = {m[1], SplitModifiers(m[4])};
  if (equations == std::string::npos) return model;
  const std::regex connect(
      R"(connect\(([A-Za-z0-9_]+)\.([A-Za-z0-9_]+)(\[1\])?, ([A-Za-z0-9_]+)\.([A-Za-z0-9_]+)(\[1\])?\))");
  const std::string body = text.substr(equations);
  for (std::sregex_iterator it(body.begin(), body.end(), connect), end; it != end; ++it)
    model.connects.emplace_back(std::string((*it)[1]) + "." + std::string((*it)[2]),
                                std::string((*it)[4]) + "." + std::string((*it)[5]));
  return model;
}

/// A numeric modifier value: a number, true/false (1/0) or a literal of
/// Modelica.Blocks.Types.Extrapolation (its position, 1-based, as the simulator encodes it).
inline bool ModifierNumber(const std::string& value, double& out) {
  static const std::map<std::string, double> literals = {
      {"true", 1.0},
      {"false", 0.0},
      {"Modelica.Blocks.Types.Extrapolation.HoldLastPoint", 1.0},
      {"Modelica.Blocks.Types.Extrapolation.LastTwoPoints", 2.0},
      {"Modelica.Blocks.Types.Extrapolation.Periodic", 3.0},
      {"Modelica.Blocks.Types.Smoothness.LinearSegments", 1.0},
      {"Modelica.Blocks.Types.Smoothness.ConstantSegments", 3.0}};
  if (auto it = literals.find(value); it != literals.end()) {
    out = it->second;
    return true;
  }
  try {
    std::size_t used = 0;
    out = std::stod(value, &used);
    return used == value.size();
  } catch (const std::exception&) {
    return false;
  }
}

/// A matrix modifier "[1, 2; 3, 4]" as rows; empty when it is not one.
inline std::vector<std::vector<double>> ModifierMatrix(const std::string& value) {
  std::vector<std::vector<double>> rows;
  if (value.size() < 2 || value.front() != '[' || value.back() != ']') return rows;
  std::istringstream in(value.substr(1, value.size() - 2));
  for (std::string row; std::getline(in, row, ';');) {
    rows.emplace_back();
    std::istringstream cells(row);
    for (std::string cell; std::getline(cells, cell, ',');) {
      double v = 0;
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      if (!ModifierNumber(cell, v)) return {};
      rows.back().push_back(v);
    }
  }
  return rows;
}

/// Union-find over "instance.port" names.
struct PortGroups {
  std::map<std::string, std::string> parent;
  std::string Root(const std::string& a) {
    if (!parent.count(a)) parent[a] = a;
    return parent[a] == a ? a : parent[a] = Root(parent[a]);
  }
  void Join(const std::string& a, const std::string& b) { parent[Root(a)] = Root(b); }
};

}  // namespace highlift::testing
