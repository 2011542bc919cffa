// Checks of numeric option values, applied to the text before CLI11 converts it (add the
// integer one with transform(), which lets it hand CLI11 the number in plain decimal). CLI11's own
// conversion accepts octal and hex ("010" is 8), reads "-1" as the largest unsigned value, clamps
// integers that overflow, and turns 1e400 into infinity; these checks refuse each of those and
// say which range the option takes.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace holefill::cli {

// A decimal whole number (optional '-', digits only) in [min, max].
CLI::Validator whole_number(std::int64_t min, std::int64_t max);

// A finite decimal number in [min, max]; with `exclusive_min`, in (min, max]. Numbers too small
// to be represented exactly (4e-324) are accepted at their nearest double, as strtod gives them.
CLI::Validator real_number(double min, double max, bool exclusive_min = false);

}  // namespace holefill::cli
