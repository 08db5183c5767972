// Points of the parameter domains: the uncertain parameters of a project, deterministic samplers
// of their box (corners, interior points, points one ulp inside a bound), and the project fixed
// at one point. The enclosures of size and peak are checked against such points (the soundness
// property test) and measured by them (tightness: enclosure width / hull of the sampled values).
//
//   const auto uncertain = highlift::reduced_models::UncertainParameters(project);
//   highlift::reduced_models::DomainSampler sampler(uncertain, /*seed=*/7);
//   const Project point = highlift::reduced_models::FixParameters(project, uncertain, sampler.Interior());
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "highlift/core/project.h"

namespace highlift::reduced_models {

/// A scalar parameter with a value and a bounded, non-empty, non-point domain (its own or the
/// catalogue default): the analyses enclose it over `domain`.
struct UncertainParameter {
  std::string component;
  std::string parameter;
  Domain domain;  ///< SI
};

/// Every uncertain parameter of the project's components, in component and catalogue order.
std::vector<UncertainParameter> UncertainParameters(const Project& project);

/// The project with parameter i fixed at x[i]: nominal x[i], a point domain, provenance user.
/// Throws InputError when x has the wrong size or a value lies outside its domain.
Project FixParameters(const Project& project, const std::vector<UncertainParameter>& uncertain,
                      const std::vector<double>& x);

/// Deterministic points of the box of the uncertain parameters (the same seed gives the same
/// sequence on every machine: the generator is std::mt19937_64, whose output the standard fixes,
/// and the mapping to doubles is our own).
class DomainSampler {
 public:
  DomainSampler(std::vector<UncertainParameter> uncertain, std::uint64_t seed);

  std::size_t dimension() const { return uncertain_.size(); }
  /// Corner k of 2^dimension (bit i set: parameter i at its upper bound).
  std::vector<double> Corner(std::uint64_t k) const;
  /// A random corner.
  std::vector<double> RandomCorner();
  /// A uniformly distributed interior point.
  std::vector<double> Interior();
  /// Every coordinate one ulp inside a randomly chosen bound of its domain.
  std::vector<double> NearBound();
  /// The next point of a mixed sequence: every corner first when there are at most
  /// kAllCorners of them; after that (or else from the start) a random corner every fourth
  /// point and interior and near-bound points in turn between them.
  std::vector<double> Next();

  static constexpr std::uint64_t kAllCorners = 64;

 private:
  double Uniform01();
  std::vector<UncertainParameter> uncertain_;
  std::mt19937_64 random_;
  std::uint64_t drawn_ = 0;
};

}  // namespace highlift::reduced_models
