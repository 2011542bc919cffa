// Runs `holefill ARGS...` in process with captured streams (link holefill_cli_lib to use it).
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "cli.h"

namespace holefill::testing {

struct CliRun {
  int code;
  std::string out, err;
};

inline CliRun run_cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = cli::run(args, out, err);
  return {code, out.str(), err.str()};
}

}  // namespace holefill::testing
