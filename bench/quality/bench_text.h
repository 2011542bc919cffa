// What the quality programs' command lines and Markdown tables share (holefill-quality,
// holefill-features).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace holefill::quality {

// A wrong command line: main prints the message and the usage, and exits with 2.
struct UsageError {
  std::string message;
};

// The non-empty parts of a comma-separated list ("a,b,,c": a, b, c).
std::vector<std::string> split(const std::string& text);

// What the programs' main does: returns run(); a UsageError prints "PROGRAM: message" and `usage`
// on stderr and gives 2, any other exception "PROGRAM: what" and 1.
int run_guarded(const char* program, const char* usage, const std::function<int()>& run);

// `value` with `decimals` digits after the point; "–" for NaN.
std::string format(double value, int decimals);

}  // namespace holefill::quality
