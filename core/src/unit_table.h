// The built-in unit table (issue 30): the units of the examples and the catalogue, converted
// without reading the UDUNITS-2 database (5 ms of every process that loads a project). Each
// entry is what UDUNITS-2 gives for that text, bit for bit (tests/core/units_test.cc checks
// every entry against the database). Internal to core; the tests include it.
#pragma once

#include <span>
#include <string_view>

#include "highlift/core/units.h"

namespace highlift::detail {

struct BuiltInUnit {
  std::string_view text;        ///< the unit text as written (trimmed), e.g. "N*m/rad"
  UnitConversion conversion;    ///< what UDUNITS-2's default database gives for it
};

/// Every entry of the table.
std::span<const BuiltInUnit> BuiltInUnits();

/// True when ParseUnit may answer from the table: UDUNITS-2 would read its default database
/// (UDUNITS2_XML_PATH is not set) and that file is readable. Otherwise every unit goes to
/// UDUNITS-2, as before the table, so a custom database or a missing one behaves as it did.
bool BuiltInUnitsApply();

/// UDUNITS-2 alone (no table, no cache): what ParseUnit gave before the table.
UnitConversion ParseUnitWithDatabase(std::string_view unit);

}  // namespace highlift::detail
