#include "bench_text.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <sstream>

namespace holefill::quality {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

int run_guarded(const char* program, const char* usage, const std::function<int()>& run) {
  try {
    return run();
  } catch (const UsageError& error) {
    std::cerr << program << ": " << error.message << "\n" << usage;
    return 2;
  } catch (const std::exception& error) {
    std::cerr << program << ": " << error.what() << "\n";
    return 1;
  }
}

std::string format(double value, int decimals) {
  if (std::isnan(value)) return "–";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace holefill::quality
