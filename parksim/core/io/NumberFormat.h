#pragma once
// Numbers as text, independent of the C and C++ locales. printf, iostreams and strtod follow
// LC_NUMERIC, so inside a host program that set a decimal-comma locale (de_DE) they write
// "0,1" and stop reading at the first '.'; std::to_chars and std::from_chars never do. Every
// parksim file writer and reader, and every number in a message or figure label, goes through
// these functions.

#include <string>
#include <string_view>

namespace parksim {

/// Shortest text that reads back as exactly `value` ("0.1", "1e-05", "-3"); "nan", "inf",
/// "-inf" for non-finite values.
std::string formatShortest(double value);
/// Appends formatShortest(value) to `out` without a temporary (for large files).
void appendShortest(std::string& out, double value);

/// Appends `value` with 17 significant digits, as printf("%.17g") in the C locale: enough to
/// read back exactly, and the digits parksim's CSV files have always had, so a plan executed
/// again writes the same bytes as before the files became locale-independent.
void appendRoundTrip(std::string& out, double value);

/// Fixed notation with `decimals` digits after the point, as printf("%.*f").
std::string formatFixed(double value, int decimals);

/// `significant` significant digits, fixed or scientific notation whichever is shorter, no
/// trailing zeros, as printf("%.*g").
std::string formatGeneral(double value, int significant = 6);

/// `text` right-aligned in a field of `width` characters (as printf's "%6s"); longer text is
/// returned whole.
std::string padLeft(std::string text, std::size_t width);

/// Parses the whole of `text` as a double ("1.5", "-2e-3", "inf", "nan"; a leading '+' is
/// accepted). False when any character is left over or nothing parses; `out` is then unchanged.
bool parseDouble(std::string_view text, double& out);

/// Parses the whole of `text` as a decimal integer (a leading '+' is accepted).
bool parseInt(std::string_view text, long long& out);

}  // namespace parksim
