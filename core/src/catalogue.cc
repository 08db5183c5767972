// The catalogue of drive-system component types: the registry that project loading, validation
// and every analysis read. The declarations themselves (ports, parameters, roles) live in each
// type's own file, model/src/components/<type>.cc; the model layer's registry installs them here
// (InstallComponentCatalogue), since core sits below the model layer.
#include "highlift/core/catalogue.h"

#include <algorithm>
#include <cctype>

#include "highlift/core/error.h"

namespace highlift {

namespace {

constexpr std::pair<ReferenceSide, const char*> kSideNames[] = {
    {ReferenceSide::kNone, "none"},
    {ReferenceSide::kMotor, "motor"},
    {ReferenceSide::kPduOutput, "pdu_output"},
    {ReferenceSide::kShaft, "shaft"},
    {ReferenceSide::kActuatorInput, "actuator_input"},
    {ReferenceSide::kActuatorOutput, "actuator_output"},
};

}  // namespace

const char* ToString(ReferenceSide side) {
  for (const auto& [s, name] : kSideNames)
    if (s == side) return name;
  return "none";
}

std::optional<ReferenceSide> ParseReferenceSide(std::string_view name) {
  for (const auto& [s, n] : kSideNames)
    if (name == n) return s;
  return std::nullopt;
}

const char* ReferenceSideLabel(ReferenceSide side) {
  switch (side) {
    case ReferenceSide::kNone: return "";
    case ReferenceSide::kMotor: return "motor side";
    case ReferenceSide::kPduOutput: return "PDU output";
    case ReferenceSide::kShaft: return "shaft side";
    case ReferenceSide::kActuatorInput: return "actuator input";
    case ReferenceSide::kActuatorOutput: return "actuator output";
  }
  return "";
}

const PortSpec* ComponentTypeSpec::FindPort(std::string_view port) const {
  for (const auto& p : ports)
    if (p.name == port) return &p;
  return nullptr;
}

const PortSpec* ComponentTypeSpec::GearedPort() const {
  for (const auto& p : ports)
    if (!p.speed_ratio.empty()) return &p;
  return nullptr;
}

const ParameterSpec* ComponentTypeSpec::FindParameter(std::string_view parameter) const {
  for (const auto& p : parameters)
    if (p.name == parameter) return &p;
  return nullptr;
}

namespace {

/// The declarations of the component types, installed by the model layer.
ComponentCatalogueProvider component_catalogue = nullptr;

std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string Lower(std::string_view s) {
  std::string r(s);
  for (char& ch : r) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return r;
}

}  // namespace

void InstallComponentCatalogue(ComponentCatalogueProvider provider) { component_catalogue = provider; }

bool ComponentCatalogueInstalled() { return component_catalogue != nullptr; }

const std::vector<ComponentTypeSpec>& ComponentTypes() {
  if (!component_catalogue)
    throw InternalError(
        "no component catalogue is installed: the component types are declared in the model layer "
        "(model/src/components/<type>.cc); link highlift::model, whose registry installs them when the "
        "program starts, or call highlift::model::InstallComponentCatalogue()");
  return component_catalogue();
}

const ComponentTypeSpec* FindComponentType(std::string_view name) {
  for (const auto& t : ComponentTypes())
    if (t.name == name) return &t;
  return nullptr;
}

std::vector<std::string> ComponentTypesWith(bool ComponentRoles::*role) {
  std::vector<std::string> names;
  for (const auto& t : ComponentTypes())
    if (t.roles.*role) names.push_back(t.name);
  return names;
}

ComponentRoles RolesOf(std::string_view type) {
  const ComponentTypeSpec* spec = FindComponentType(type);
  return spec ? spec->roles : ComponentRoles{};
}

std::vector<std::string> ComponentTypeNames() {
  std::vector<std::string> names;
  for (const auto& t : ComponentTypes()) names.push_back(t.name);
  return names;
}

std::vector<std::string> Suggest(std::string_view name, const std::vector<std::string>& candidates,
                                 std::size_t max_results) {
  // Close in edit distance (case-insensitive), or one contains the other ("gra" -> "geared_...").
  const std::string lower = Lower(name);
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& c : candidates) {
    std::size_t d = EditDistance(name, c);
    const std::string lc = Lower(c);
    if (d > limit && lower.size() >= 3 && (lc.find(lower) != std::string::npos || lower.find(lc) != std::string::npos))
      d = limit;
    if (d <= limit) scored.emplace_back(d, c);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  for (const auto& s : scored) {
    if (out.size() >= max_results) break;
    if (std::find(out.begin(), out.end(), s.second) == out.end()) out.push_back(s.second);
  }
  return out;
}

std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  const auto close = Suggest(name, candidates);
  if (close.empty()) return "";
  std::string out = "; did you mean ";
  for (std::size_t i = 0; i < close.size(); ++i) {
    if (i > 0) out += (i + 1 == close.size()) ? " or " : ", ";
    out += "'" + close[i] + "'";
  }
  return out + "?";
}

std::string SuggestionHint(std::string_view name, const std::vector<std::string>& candidates,
                           const std::string& label) {
  std::string list;
  for (std::size_t i = 0; i < candidates.size(); ++i) list += (i ? ", " : "") + candidates[i];
  if (candidates.empty()) list = "(none)";
  const std::string suggestion = DidYouMean(name, candidates);
  if (suggestion.empty()) return "; " + label + ": " + list;
  std::string capital = label;
  capital[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(capital[0])));
  return suggestion + " " + capital + ": " + list;
}

}  // namespace highlift
