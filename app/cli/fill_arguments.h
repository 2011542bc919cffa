// The options of `holefill fill`: registered on a CLI11 subcommand with the defaults of the
// library's option structs (so the help prints the real ones), then turned into those structs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "holefill/fill.h"
#include "preparation.h"

namespace CLI {
class App;  // CLI11's (CLI/CLI.hpp): only the .cpp files that register options include it
}  // namespace CLI

namespace holefill::cli {

struct FillArguments {
  std::vector<std::string> inputs;  // as typed: meshes or folders (several: a batch)
  unsigned jobs = 0;                // meshes of a batch filled at once (-j; 0: one per core)
  std::string input;                // the mesh being filled
  std::string output;
  std::string report_path;
  std::string format;                  // of "-" (standard input or output): obj, off, ply or stl
  std::vector<std::int64_t> hole_ids;  // as typed; checked against the mesh's holes later
  std::vector<std::string> bridges;    // "A,B" as typed; checked against the mesh's holes later
  HoleSelection selection;             // max_boundary_edges; hole_ids once checked
  FillOptions options;
  PreparationChoice preparation;  // stitching, small pieces, borders

  // Texts and units of the command line, converted into `options` by finish().
  std::string weight, stage, smooth, fair_weights, remesh, islands;
  double fold_limit_degrees = 0.0;
};

// Adds fill's options to `command`, writing into `arguments` (which must outlive the parse).
void add_fill_options(CLI::App& command, FillArguments& arguments);

// Adds the options that say how to fill (every option of fill's but MESH, -o, --format and
// --report), writing into `arguments`.
void add_fill_choices(CLI::App& command, FillArguments& arguments);

// Those options parsed from `args` (e.g. {"--tau", "2"}) and finished (finish_fill_options), for
// callers that take fill's options from elsewhere than a command line (the Python module).
// Throws UsageError with CLI11's message for an unknown option or a value out of its range.
FillArguments parse_fill_choices(const std::vector<std::string>& args);

// One option of add_fill_choices as the help shows it: its long name ("--tau"), the help text
// and the default.
struct OptionHelp {
  std::string flag, description, default_text;
};
std::vector<OptionHelp> fill_choice_help();

// Adds --feature-angle (features.h), the dihedral angle above which an edge is a feature.
void add_feature_angle_option(CLI::App& command, FeatureOptions& features);

// Adds --threads: how many threads do `work` ("read and prepare the mesh"), 0 every core.
void add_threads_option(CLI::App& command, unsigned& threads, const std::string& work);

// Adds --format, the format of a mesh read from standard input or written to standard output.
void add_format_option(CLI::App& command, std::string& format);

// Converts what the command line gave into `arguments.options` and `.selection` (after parsing).
void finish_fill_options(FillArguments& arguments);

}  // namespace holefill::cli
