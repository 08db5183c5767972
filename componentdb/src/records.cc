#include "highlift/componentdb/records.h"

namespace highlift::componentdb {

std::string ToString(Tag tag) {
  switch (tag) {
    case Tag::kPublished: return "P";
    case Tag::kPublishedLow: return "P-low";
    case Tag::kEstimate: return "E";
  }
  return "E";
}

std::optional<Tag> TagFromString(const std::string& text) {
  if (text == "P") return Tag::kPublished;
  if (text == "P-low") return Tag::kPublishedLow;
  if (text == "E") return Tag::kEstimate;
  return std::nullopt;
}

double Quantity::Representative() const {
  if (value_si) return *value_si;
  return 0.5 * (domain_si.lo + domain_si.hi);
}

bool operator==(const Quantity& a, const Quantity& b) {
  return a.name == b.name && a.value == b.value && a.lo == b.lo && a.hi == b.hi && a.unit == b.unit &&
         a.value_si == b.value_si && a.domain_si == b.domain_si && a.tag == b.tag &&
         a.source == b.source;
}

const Quantity* Part::Find(const std::string& parameter) const {
  for (const auto& q : parameters)
    if (q.name == parameter) return &q;
  return nullptr;
}

bool operator==(const Part& a, const Part& b) {
  return a.type == b.type && a.designation == b.designation && a.program == b.program &&
         a.supplier == b.supplier && a.note == b.note && a.parameters == b.parameters;
}

const Quantity* Material::Find(const std::string& property) const {
  for (const auto& q : properties)
    if (q.name == property) return &q;
  return nullptr;
}

bool operator==(const Material& a, const Material& b) {
  return a.name == b.name && a.note == b.note && a.properties == b.properties;
}

const std::vector<std::string>& MaterialPropertyNames() {
  static const std::vector<std::string> names{"shear_modulus", "density", "allowable_shear_stress"};
  return names;
}

}  // namespace highlift::componentdb
