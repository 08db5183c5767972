#include "highlift/model/network.h"

#include <cmath>

#include "highlift/core/error.h"
#include "highlift/core/message_number.h"

namespace highlift::model {

namespace {

std::vector<std::string> TypeNames() {
  std::vector<std::string> names;
  for (const auto& t : ElementTypes()) names.push_back(t.name);
  return names;
}

std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates) {
  auto s = Suggest(name, candidates);
  return s.empty() ? "" : "; did you mean '" + s.front() + "'?";
}

bool ValidId(std::string_view id) {
  if (id.empty() || !(std::isalpha(static_cast<unsigned char>(id[0])) || id[0] == '_')) return false;
  for (char c : id)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

}  // namespace

void Network::AddElement(std::string_view type, std::string_view id, ElementParameters parameters) {
  const std::string sid(id), stype(type);
  const ComponentTypeSpec* spec = FindElementType(type);
  if (spec == nullptr)
    throw InputError("element '" + sid + "': unknown element type '" + stype + "'" +
                     DidYouMean(stype, TypeNames()));
  if (!ValidId(id))
    throw InputError("element id '" + sid + "' is not valid: use a letter or '_' followed by "
                     "letters, digits and '_'");
  if (Find(id) != nullptr)
    throw InputError("element id '" + sid + "' is used twice; give each element its own id");
  NetworkElement e;
  e.id = sid;
  e.type = stype;
  e.spec = spec;
  std::vector<std::string> names;
  for (const auto& p : spec->parameters) names.push_back(p.name);
  for (const auto& [name, value] : parameters.scalars) {
    const ParameterSpec* p = spec->FindParameter(name);
    if (p == nullptr || p->kind == ParameterKind::kTable)
      throw InputError("element '" + sid + "' (" + stype + "): unknown parameter '" + name + "'" +
                       DidYouMean(name, names));
    if (!std::isfinite(value))  // a value derived from a component's parameters (drive networks)
      throw InputError("element '" + sid + "' (" + stype + "): parameter '" + name + "' = " +
                       FormatMessageNumber(value) + " is not finite; in a drive network it is computed from the parameters of the component the element "
                       "belongs to (its id's prefix): check their values and units");
    if (!p->valid_range.contains(value))
      throw InputError("element '" + sid + "' (" + stype + "): parameter '" + name + "' = " +
                       FormatMessageNumber(value) + " is outside its valid range [" +
                       FormatMessageNumber(p->valid_range.lo) + ", " + FormatMessageNumber(p->valid_range.hi) + "]");
    if (p->kind == ParameterKind::kBoolean && value != 0 && value != 1)
      throw InputError("element '" + sid + "' (" + stype + "): parameter '" + name +
                       "' is a flag; give true or false");
    e.given[name] = true;
  }
  for (const auto& [name, table] : parameters.tables) {
    const ParameterSpec* p = spec->FindParameter(name);
    if (p == nullptr || p->kind != ParameterKind::kTable)
      throw InputError("element '" + sid + "' (" + stype + "): unknown table parameter '" + name +
                       "'" + DidYouMean(name, names));
    (void)table;
  }
  for (const auto& p : spec->parameters) {
    if (p.kind == ParameterKind::kTable || p.kind == ParameterKind::kText) continue;
    if (parameters.scalars.count(p.name)) continue;
    if (p.nominal) {
      parameters.scalars[p.name] = *p.nominal;
    } else if (!p.optional) {
      throw InputError("element '" + sid + "' (" + stype + "): parameter '" + p.name + "' (" +
                       p.description + ", " + p.unit + ") is required; give its value");
    }
  }
  e.parameters = std::move(parameters);
  index_.emplace(e.id, elements_.size());
  elements_.push_back(std::move(e));
}

const NetworkElement* Network::Find(std::string_view id) const {
  const auto it = index_.find(id);
  return it == index_.end() ? nullptr : &elements_[it->second];
}

void Network::Adopt(const NetworkElement& element) {
  if (Find(element.id) != nullptr)
    throw InputError("element id '" + element.id + "' is used twice; give each element its own id");
  index_.emplace(element.id, elements_.size());
  elements_.push_back(element);
}

void Network::Adopt(const NetworkConnection& connection) {
  Connect(connection.a.ToString(), connection.b.ToString());
}

PortRef Network::ParsePort(std::string_view text) const {
  const auto dot = text.rfind('.');
  if (dot == std::string_view::npos)
    throw InputError("port '" + std::string(text) + "' must be written 'element.port'");
  PortRef ref{std::string(text.substr(0, dot)), std::string(text.substr(dot + 1))};
  const NetworkElement* e = Find(ref.component);
  if (e == nullptr) {
    std::vector<std::string> ids;
    for (const auto& x : elements_) ids.push_back(x.id);
    throw InputError("connection to '" + std::string(text) + "': no element '" + ref.component +
                     "'" + DidYouMean(ref.component, ids));
  }
  if (e->spec->FindPort(ref.port) == nullptr) {
    std::vector<std::string> ports;
    for (const auto& p : e->spec->ports) ports.push_back(p.name);
    throw InputError("connection to '" + std::string(text) + "': element '" + e->id + "' (" +
                     e->type + ") has no port '" + ref.port + "'" + DidYouMean(ref.port, ports));
  }
  return ref;
}

void Network::Connect(std::string_view a, std::string_view b) {
  PortRef pa = ParsePort(a), pb = ParsePort(b);
  const PortKind ka = Find(pa.component)->spec->FindPort(pa.port)->kind;
  const PortKind kb = Find(pb.component)->spec->FindPort(pb.port)->kind;
  if (ka != kb)
    throw InputError("connection " + pa.ToString() + " - " + pb.ToString() + ": a " +
                     PortKindName(ka) + " port cannot be connected to a " + PortKindName(kb) +
                     " port; connect ports of the same kind");
  connections_.push_back({std::move(pa), std::move(pb)});
}

Network NetworkFromProject(const Project& project) {
  if (project.elements.empty())
    throw InputError("project '" + project.name +
                     "' has no element network ('elements' is empty); the simulator runs element "
                     "networks (the drive-system translation is not available yet)");
  Network net;
  for (const Component& c : project.elements) {
    try {
      ElementParameters p;
      const ComponentTypeSpec* spec = FindElementType(c.type);
      for (const auto& [name, value] : c.parameters) {
        if (!value.nominal) {
          // Defaults that the reader filled from the catalogue without a nominal value (e.g.
          // optional initial values) are simply absent.
          if (value.provenance == Provenance::kDefault) continue;
          throw InputError("element '" + c.id + "': parameter '" + name +
                           "' needs a value (an interval alone cannot be simulated)");
        }
        if (value.provenance == Provenance::kDefault && spec != nullptr) {
          const ParameterSpec* ps = spec->FindParameter(name);
          if (ps != nullptr && ps->optional) continue;
        }
        p.scalars[name] = *value.nominal;
      }
      for (const auto& [name, table] : c.tables) p.tables[name] = table;
      net.AddElement(c.type, c.id, std::move(p));
    } catch (InputError& e) {
      if (!c.where.empty()) throw InputError(e.message(), c.where);
      throw;
    }
  }
  for (const Connection& k : project.element_connections) {
    try {
      net.Connect(k.a.ToString(), k.b.ToString());
    } catch (InputError& e) {
      if (!k.where.empty()) throw InputError(e.message(), k.where);
      throw;
    }
  }
  return net;
}

}  // namespace highlift::model
