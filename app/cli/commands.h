// The subcommands of `holefill`, each given its parsed arguments and the streams to write to.
#pragma once

#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>

#include "cli.h"
#include "fill_arguments.h"

namespace holefill::cli {

// A command line that parsed but asks for something impossible (a hole the mesh lacks, an
// output format holefill cannot write): reported like CLI11's own errors, exit kUsage.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// -q: no table on stdout and no progress (warnings and errors still on stderr); -v: progress
// lines from the start instead of after a second.
enum class Verbosity { Quiet, Normal, Verbose };

struct Streams {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
  Verbosity verbosity = Verbosity::Normal;
};

struct InfoArguments {
  std::string input;
  std::string format;  // of standard input, for an input of "-"
  bool json = false;
  PreparationChoice preparation;  // stitching, small pieces, borders (islands from `islands`)
  std::string islands = "on";     // --islands: "off" skips island detection
  FeatureOptions features;        // which sharp features entering a hole are listed
  unsigned threads = 0;           // --threads: reading and preparing (0: every core)
};

int run_info(const InfoArguments& arguments, const Streams& streams);
// Runs `work` and returns its exit code, or the code of what it throws (UsageError, FileError,
// bad_alloc, anything else), after saying why on `err` as the command line does.
int exit_code_of(const std::function<int()>& work, std::ostream& err);
int run_fill(FillArguments& arguments, const Streams& streams);

}  // namespace holefill::cli
