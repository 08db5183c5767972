// The benchmark families of ../shared/reference/icsp/README.md, generated from their
// definitions: `dt` (a drive-train sizing chain), `dtinf` (the same chain, provably infeasible)
// and `rnd` (random sparse networks with a known solution). Used by the reference tests, which
// compare the generated text with the committed net files, and by the benchmarks.
#pragma once

#include <string>
#include <vector>

#include "highlift/icsp/network.h"

namespace highlift::icsp {

struct ReferenceVariable {
  std::string name;
  double lo = 0.0;
  double hi = 0.0;
};

/// One constraint in the canonical form of the reference (TAU, LEQK, TREC, LEQV, SUM, EQV,
/// MULADD, SQRTSUB); unused variable slots are -1, unused constants 0.
struct ReferenceConstraint {
  std::string type;
  int v[3] = {-1, -1, -1};
  double k1 = 0.0;
  double k2 = 0.0;
};

struct ReferenceNetwork {
  std::string header;                        ///< first comment line, e.g. "dt n_stations=20"
  std::vector<ReferenceVariable> variables;
  std::vector<ReferenceConstraint> constraints;
  std::vector<double> witness;               ///< a satisfying point (empty for dtinf)
};

/// The dt family (or dtinf when `infeasible`) of the given size (SIZE in the README: n =
/// max(1, size/5) stations, 5n+2 constraints).
ReferenceNetwork MakeDriveTrainNetwork(int size, bool infeasible);
/// The rnd family with `size` constraints and seed 20240601.
ReferenceNetwork MakeRandomNetwork(int size);
/// The net file text exactly as in nets/<family>_<n>.txt (values with 17 significant digits).
std::string ToNetText(const ReferenceNetwork& net);
/// Builds the expression trees of the canonical form into a Network.
Network BuildNetwork(const ReferenceNetwork& net);

}  // namespace highlift::icsp
