// Reading, validating and writing component-database records as CSV or JSON.
//
// CSV (one row per parameter; a spreadsheet-friendly long format; rows are counted like a
// spreadsheet, the header being row 1):
//   type,designation,program,supplier,note,parameter,value,min,max,unit,tag,source
//   geared_rotary_actuator,GRA-200-A380C,A380-class flap,,,ratio,200,,,1,E,domain.md s3
// `type` is a catalogue component type or `material` (then `parameter` is a material property:
// shear_modulus, density, allowable_shear_stress). Rows of one part follow each other; the part
// columns (program, supplier, note) may be left empty after its first row.
//
// JSON:
//   {"format": "highlift-componentdb/1",
//    "materials": [{"name": "Ti-6Al-4V", "note": "", "properties": {"shear_modulus":
//        {"value": 44, "min": 43, "max": 51, "unit": "GPa", "tag": "P-low", "source": "..."}}}],
//    "parts": [{"type": "geared_rotary_actuator", "designation": "GRA-200-A380C",
//               "program": "A380-class flap", "supplier": "", "note": "",
//               "parameters": {"ratio": {"value": 200, "unit": "1", "tag": "E", "source": "..."}}}]}
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "highlift/componentdb/records.h"

namespace highlift::componentdb {

/// The CSV header, in column order.
const std::vector<std::string>& CsvColumns();

/// Parses CSV text into records (syntax only; see ValidateRecords). `file_name` prefixes
/// messages and origins. Throws InputError naming the row and the problem.
Records ParseCsv(const std::string& text, const std::string& file_name);
/// Parses JSON text into records (syntax only). Unknown keys are errors.
Records ParseJson(const std::string& text, const std::string& file_name);
/// Reads a .csv or .json file (by extension), parses and validates it.
Records ReadRecords(const std::filesystem::path& file);

/// Checks every record against the component catalogue and fills in the SI values: known type,
/// known scalar parameter of that type, a unit of the right dimension, a value or an interval
/// (min <= value <= max) inside the parameter's valid range, a tag P / P-low / E, a source, no
/// duplicate designation or parameter, every material property present. Throws InputError
/// naming the origin (file and row), the problem and what would be valid.
void ValidateRecords(Records& records);

/// Records as CSV / JSON in the formats above. Numbers are written with 17 significant digits
/// so that reading them back gives the same doubles.
std::string ToCsv(const Records& records);
nlohmann::ordered_json ToJson(const Records& records);
/// Writes .csv or .json (by extension) atomically.
void WriteRecords(const Records& records, const std::filesystem::path& file);

}  // namespace highlift::componentdb
