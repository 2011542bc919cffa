#include "number_checks.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace holefill::cli {
namespace {

std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string range_text(double min, double max, bool exclusive_min) {
  const bool unbounded = max == std::numeric_limits<double>::max();
  if (unbounded) return (exclusive_min ? "> " : ">= ") + shortest(min);
  return std::string(exclusive_min ? "in (" : "in [") + shortest(min) + ", " + shortest(max) + "]";
}

}  // namespace

CLI::Validator whole_number(std::int64_t min, std::int64_t max) {
  const std::string range = max == std::numeric_limits<std::int64_t>::max()
                                ? ">= " + std::to_string(min)
                                : "in " + std::to_string(min) + ".." + std::to_string(max);
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        std::int64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || stop != end ||
            (error != std::errc() && error != std::errc::result_out_of_range)) {
          return "needs a whole number " + range + ", got '" + text + "'";
        }
        // Past either end of int64 from_chars gives no value: the sign says which end.
        const bool too_large =
            error == std::errc::result_out_of_range ? text[0] != '-' : value > max;
        if (too_large) return "must be at most " + std::to_string(max) + ", got " + text;
        if (error == std::errc::result_out_of_range || value < min) {
          return "must be " + range + ", got " + text;
        }
        text = std::to_string(value);  // what CLI11 then converts: no octal or hex reading
        return {};
      },
      "", "whole number");
}

CLI::Validator real_number(double min, double max, bool exclusive_min) {
  const std::string range = range_text(min, max, exclusive_min);
  return CLI::Validator(
      [min, max, exclusive_min, range](std::string& text) -> std::string {
        char* stop = nullptr;
        errno = 0;
        const double value = std::strtod(text.c_str(), &stop);
        const bool parsed = !text.empty() && stop == text.c_str() + text.size() &&
                            !std::isspace(static_cast<unsigned char>(text[0]));
        if (!parsed || std::isnan(value)) return "needs a number " + range + ", got '" + text + "'";
        const bool below = exclusive_min ? !(value > min) : value < min;
        if (std::isinf(value) || below || value > max) return "must be " + range + ", got " + text;
        return {};
      },
      "", "number");
}

}  // namespace holefill::cli
