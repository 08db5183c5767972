// The one formatter of numbers in messages (errors, warnings, notes).
#pragma once

#include <string>

namespace highlift {

/// A number in a message: at most `significant` significant digits and no trailing zeros
/// ("0.01", "25.3", "1e-303", "1.7e308", "4.94066e-324"), "0" for -0, "nan" for every NaN,
/// "inf"/"-inf". std::to_string prints 309 digits for 1e308, "0.000000" for 1e-9 and
/// "-0.000000" for -1e-12; FormatNumber (text_table.h) is for the columns of tables.
std::string FormatMessageNumber(double value, int significant = 6);

}  // namespace highlift
