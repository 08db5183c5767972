#include "highlift/reduced_models/sampling.h"

#include <cmath>
#include <limits>

#include "highlift/core/catalogue.h"
#include "highlift/core/error.h"
#include "highlift/core/message_number.h"

namespace highlift::reduced_models {

std::vector<UncertainParameter> UncertainParameters(const Project& project) {
  std::vector<UncertainParameter> out;
  for (const Component& c : project.components) {
    const ComponentTypeSpec* type = FindComponentType(c.type);
    if (!type) continue;
    for (const ParameterSpec& spec : type->parameters) {
      if (spec.kind != ParameterKind::kScalar) continue;
      auto it = c.parameters.find(spec.name);
      // The analyses' view of a value: the component's own, else the catalogue default; a
      // default domain without a nominal value is only the valid range, not a value.
      const bool own = it != c.parameters.end();
      const Domain domain = own ? it->second.domain : spec.default_domain;
      const bool has_value = own ? (it->second.nominal || it->second.provenance != Provenance::kDefault)
                                 : spec.nominal.has_value();
      if (has_value && domain.bounded() && !domain.empty() && !domain.is_point())
        out.push_back({c.id, spec.name, domain});
    }
  }
  return out;
}

Project FixParameters(const Project& project, const std::vector<UncertainParameter>& uncertain,
                      const std::vector<double>& x) {
  if (x.size() != uncertain.size())
    throw InputError("FixParameters: " + std::to_string(x.size()) + " values for " + std::to_string(uncertain.size()) +
                     " uncertain parameters; give one value per parameter");
  Project point = project;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const UncertainParameter& u = uncertain[i];
    if (!(x[i] >= u.domain.lo && x[i] <= u.domain.hi))
      throw InputError("FixParameters: " + u.component + "." + u.parameter + " = " + FormatMessageNumber(x[i]) +
                       " lies outside its domain [" + FormatMessageNumber(u.domain.lo) + ", " + FormatMessageNumber(u.domain.hi) +
                       "]; give a value inside it");
    Component* c = point.FindComponent(u.component);
    if (!c) throw InputError("FixParameters: no component '" + u.component + "' in project '" + project.name + "'");
    Parameter& p = c->parameters[u.parameter];
    p.nominal = x[i];
    p.domain = Domain::Point(x[i]);
    p.provenance = Provenance::kUser;
    p.database_part.clear();
  }
  return point;
}

DomainSampler::DomainSampler(std::vector<UncertainParameter> uncertain, std::uint64_t seed)
    : uncertain_(std::move(uncertain)), random_(seed) {}

double DomainSampler::Uniform01() {
  // 53 random bits -> [0, 1), independent of the standard library's distributions.
  return static_cast<double>(random_() >> 11) * 0x1.0p-53;
}

std::vector<double> DomainSampler::Corner(std::uint64_t k) const {
  std::vector<double> x(uncertain_.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const bool upper = i < 64 && ((k >> i) & 1u);
    x[i] = upper ? uncertain_[i].domain.hi : uncertain_[i].domain.lo;
  }
  return x;
}

std::vector<double> DomainSampler::RandomCorner() {
  std::vector<double> x(uncertain_.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = (random_() & 1u) ? uncertain_[i].domain.hi : uncertain_[i].domain.lo;
  return x;
}

std::vector<double> DomainSampler::Interior() {
  std::vector<double> x(uncertain_.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Domain& d = uncertain_[i].domain;
    x[i] = std::min(d.hi, std::max(d.lo, d.lo + Uniform01() * (d.hi - d.lo)));
  }
  return x;
}

std::vector<double> DomainSampler::NearBound() {
  std::vector<double> x(uncertain_.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Domain& d = uncertain_[i].domain;
    x[i] = (random_() & 1u) ? std::nextafter(d.hi, d.lo) : std::nextafter(d.lo, d.hi);
  }
  return x;
}

std::vector<double> DomainSampler::Next() {
  const std::uint64_t n = drawn_++;
  const bool few_corners = uncertain_.size() < 63 && (std::uint64_t{1} << uncertain_.size()) <= kAllCorners;
  if (few_corners) {
    const std::uint64_t corners = std::uint64_t{1} << uncertain_.size();
    if (n < corners) return Corner(n);
  }
  if (n % 4 == 0) return RandomCorner();
  return n % 4 == 2 ? NearBound() : Interior();
}

}  // namespace highlift::reduced_models
