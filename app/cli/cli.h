// The `holefill` command line: parsing its arguments and running its subcommands, apart from
// main() so that tests can drive it with argument vectors and captured streams.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace holefill::cli {

// Exit codes, one per kind of outcome, so scripts can tell them apart.
enum ExitCode : int {
  kOk = 0,
  kSomeHolesNotFilled = 1,  // output written, but at least one selected hole failed (or was
                            // left open because every patch tried intersects the mesh)
  kUsage = 2,               // bad arguments
  kBadInput = 3,            // input file missing, unreadable or invalid
  kWriteFailed = 4,         // output or report could not be written
  kPatchesIntersect = 5,    // --allow-intersections: output written, every selected hole
                            // filled, but some patch intersects the mesh (the report names them)
  kInternalError = 6,       // an unexpected error inside holefill (a bug: please report it)
  kOutOfMemory = 7,         // memory ran out; no output was written
};

// Runs `holefill ARGS...` (args excludes the program name) with `in` as standard input (read
// for a MESH of "-"); returns the exit code. A failure to write `out` is reported on `err` after
// the files are written, and turns a successful run's code into kWriteFailed.
int run(const std::vector<std::string>& args, std::istream& in, std::ostream& out,
        std::ostream& err);
// The same with no standard input (a MESH of "-" then reads nothing).
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace holefill::cli
