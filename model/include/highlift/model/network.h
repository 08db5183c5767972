// An element network: instances of the element types of the catalogue (ElementTypes(), MSL
// names such as "Inertia", "SpringDamper", "Clutch") and the connections of their ports.
// This is the structure only, shared by the analyses that read it: the simulator
// (highlift/sim/simulator.h) assembles and integrates it, the Modelica export writes it
// (HighLift classes for HighLift element types, MSL classes for MSL ones).
//
//   highlift::model::Network net;
//   net.AddElement("Inertia", "inertia1", {.scalars = {{"J", 0.1}}});
//   net.AddElement("Fixed", "fixed");
//   net.AddElement("Spring", "spring", {.scalars = {{"c", 1e4}}});
//   net.Connect("fixed.flange", "spring.flange_a");
//   net.Connect("spring.flange_b", "inertia1.flange_a");
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "highlift/core/catalogue.h"
#include "highlift/core/project.h"

namespace highlift::model {

/// Parameter values of one element in SI: scalars (booleans and integers as 0/1 and whole
/// numbers) and tables (rows of numbers).
struct ElementParameters {
  std::map<std::string, double> scalars;
  std::map<std::string, std::vector<std::vector<double>>> tables;
};

/// One element of a network, with every catalogue parameter filled in (given or default).
struct NetworkElement {
  std::string id;                  ///< instance name, the prefix of its output columns
  std::string type;                ///< element type name (catalogue)
  const ComponentTypeSpec* spec = nullptr;
  ElementParameters parameters;    ///< given values plus catalogue defaults
  std::map<std::string, bool> given;  ///< which scalar parameters were given (initial values)
  std::string description;         ///< one line for readers (the exported model's comment)
};

struct NetworkConnection {
  PortRef a;
  PortRef b;
};

class Network {
 public:
  /// Adds an element. Throws InputError for an unknown type, a duplicate id, an unknown
  /// parameter, a missing required parameter or a value outside the valid range.
  void AddElement(std::string_view type, std::string_view id, ElementParameters parameters = {});
  /// Connects two ports given as "element.port". Throws InputError for unknown elements or
  /// ports and for connecting a flange to a signal port.
  void Connect(std::string_view a, std::string_view b);

  /// Adds an element of another network as it is (already validated, defaults filled in).
  /// Throws InputError for a duplicate id.
  void Adopt(const NetworkElement& element);
  /// Adds a connection of another network as it is (both ports must exist here).
  void Adopt(const NetworkConnection& connection);

  const std::vector<NetworkElement>& elements() const { return elements_; }
  const std::vector<NetworkConnection>& connections() const { return connections_; }
  const NetworkElement* Find(std::string_view id) const;

 private:
  PortRef ParsePort(std::string_view text) const;
  // Find by id in constant time: the simulator's flattening of composites looks up every
  // connection's two elements in networks of several hundred elements (issue 30).
  struct IdHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
  };
  std::vector<NetworkElement> elements_;
  std::unordered_map<std::string, std::size_t, IdHash, std::equal_to<>> index_;  // id -> position in elements_
  std::vector<NetworkConnection> connections_;
};

/// The element network of a project (`elements`, `element_connections`). Throws InputError
/// (with the element's source location) when the project has no elements or one is invalid.
Network NetworkFromProject(const Project& project);

}  // namespace highlift::model
