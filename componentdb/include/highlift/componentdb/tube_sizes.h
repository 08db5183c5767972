// Tube sizes: the (outer diameter, wall thickness) pairs a torque shaft may be made of, for
// `highlift optimize --tube-sizes` (docs/optimize.md).
//
// CSV, one size a row, the units in the header (any length unit UDUNITS knows):
//   designation,outer_diameter [mm],wall_thickness [mm]
//   45x1.8,45,1.8
// Blank rows and rows whose first field starts with '#' are skipped.
//
// The shipped table ("standard", data/tube_sizes.csv compiled into the library as the database seed
// is) takes outer diameters and walls from the ISO 3 preferred-number series R20 (D 20 ... 125 mm,
// wall 0.8 ... 5 mm), every pair with 10 <= D/t <= 40: an engineering convention, not a supplier's
// catalogue.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace highlift::componentdb {

struct TubeSize {
  std::string designation;     ///< e.g. "45x1.8"
  double outer_diameter = 0.0; ///< D [m]
  double wall_thickness = 0.0; ///< t [m], 0 < t <= D/2
  std::string origin;          ///< "FILE line N"
};

struct TubeSizeTable {
  std::string name;            ///< "standard" or the file it was read from
  std::vector<TubeSize> sizes; ///< in the file's order
};

/// Parses the CSV text. Throws InputError naming `file_name`, the line and what is valid: a header
/// other than designation,outer_diameter [UNIT],wall_thickness [UNIT], a unit that is not a length,
/// a row without three fields, an empty or repeated designation, a number that is not finite and
/// positive, a wall above half the diameter, no size at all.
TubeSizeTable ParseTubeSizes(const std::string& text, const std::string& file_name);

/// "standard": the shipped table; otherwise the CSV file at that path (InputError when it cannot be
/// read).
TubeSizeTable LoadTubeSizes(const std::string& file_or_standard);

/// The shipped table (parsed once).
const TubeSizeTable& StandardTubeSizes();
/// Its CSV text (data/tube_sizes.csv).
const std::string& StandardTubeSizesCsv();

}  // namespace highlift::componentdb
