#include "cli.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <functional>
#include <new>
#include <ostream>
#include <sstream>

#include "batch_command.h"
#include "commands.h"
#include "holefill/errors.h"
#include "holefill/version.h"
#include "outputs.h"

namespace holefill::cli {
namespace {

constexpr const char* kDescription =
    "holefill " HOLEFILL_VERSION ": fill holes in triangle meshes (Wei, Wu & Pang 2010)";

constexpr const char* kExitCodes =
    "Meshes are read from .obj .off .ply .stl and written as .obj .off .ply .stl.\n"
    "Exit codes: 0 ok, 1 some holes not filled (output written), 2 usage error, 3 bad input,\n"
    "4 output not written, 5 every hole filled but some patch intersects the mesh,\n"
    "6 internal error, 7 out of memory (nothing written).";

// Everything the command line can hold, alive while CLI11 parses into it.
struct CommandLine {
  CLI::App app{kDescription, "holefill"};
  CLI::App* info = nullptr;
  CLI::App* fill = nullptr;
  CLI::App* help = nullptr;
  InfoArguments info_arguments;
  std::string help_topic;
  FillArguments fill_arguments;
  bool quiet = false;
  bool verbose = false;

  CommandLine() {
    app.set_version_flag("--version", "holefill " HOLEFILL_VERSION);
    app.footer(kExitCodes);
    app.require_subcommand(1);
    app.fallthrough();  // -q and -v also after the command's name
    app.add_flag("-q,--quiet", quiet, "no table on stdout, no progress (warnings still on stderr)")
        ->excludes(app.add_flag("-v,--verbose", verbose,
                                "progress on stderr from the start, a line per percent\n"
                                "(without -v: once a fill has taken a second, a line a second)"));
    info = app.add_subcommand("info", "vertices, faces, components and a table of holes");
    info->add_option("MESH", info_arguments.input, "the mesh to describe (-: stdin)")->required();
    info->add_flag("--json", info_arguments.json, "print the counts and holes as JSON");
    add_format_option(*info, info_arguments.format);
    add_preparation_options(*info, info_arguments.preparation);
    add_islands_option(*info, info_arguments.islands);
    add_feature_angle_option(*info, info_arguments.features);
    add_threads_option(*info, info_arguments.threads, "read and prepare the mesh");
    fill = app.add_subcommand("fill", "fill holes, write the result, print a table");
    add_fill_options(*fill, fill_arguments);
    help = app.add_subcommand("help", "this text, or a command's options");
    help->add_option("COMMAND", help_topic, "info or fill")->check(CLI::IsMember({"info", "fill"}));
  }

  Verbosity verbosity() const {
    return quiet ? Verbosity::Quiet : verbose ? Verbosity::Verbose : Verbosity::Normal;
  }
};

int usage_error(const std::string& message, std::ostream& err) {
  err << "holefill: " << message << "\nRun 'holefill --help' or 'holefill COMMAND --help'.\n";
  return kUsage;
}

int dispatch(CommandLine& line, const Streams& streams) {
  std::ostream& out = streams.out;
  if (line.info->parsed()) return run_info(line.info_arguments, streams);
  if (line.fill->parsed()) {
    finish_fill_options(line.fill_arguments);
    if (is_batch(line.fill_arguments)) return run_batch(line.fill_arguments, streams);
    return run_fill(line.fill_arguments, streams);
  }
  if (line.help_topic.empty()) {
    out << line.app.help();
  } else {
    out << line.app.get_subcommand(line.help_topic)->help("holefill");
  }
  return kOk;
}

}  // namespace

int exit_code_of(const std::function<int()>& work, std::ostream& err) {
  try {
    return work();
  } catch (const UsageError& e) {
    return usage_error(e.what(), err);
  } catch (const FileError& e) {
    err << "holefill: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::bad_alloc&) {
    err << "holefill: out of memory; nothing was written\n";
    return kOutOfMemory;
  } catch (const std::exception& e) {
    err << "holefill: internal error: " << e.what() << " (please report it)\n";
    return kInternalError;
  }
}

namespace {

// A standard output that could not be written (`info > /dev/full`, a closed pipe) fails the run.
// The reason is the last system error: the failed flush's, or that of the write that failed
// first (the table is the last thing written, so nothing has overwritten it).
int check_stdout(int code, std::ostream& out, std::ostream& err) {
  if (out) {
    errno = 0;
    out.flush();
  }
  if (out) return code;
  err << "holefill: standard output could not be written" << last_system_error() << "\n";
  return code == kOk || code == kSomeHolesNotFilled || code == kPatchesIntersect ? kWriteFailed
                                                                                 : code;
}

}  // namespace

int run(const std::vector<std::string>& args, std::istream& in, std::ostream& out,
        std::ostream& err) {
  CommandLine line;
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    line.app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      return check_stdout(line.app.exit(e, out, err), out, err);  // --help, --version
    }
    return usage_error(e.what(), err);
  }
  const Streams streams{in, out, err, line.verbosity()};
  return check_stdout(exit_code_of([&] { return dispatch(line, streams); }, err), out, err);
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::istringstream nothing;
  return run(args, nothing, out, err);
}

}  // namespace holefill::cli
