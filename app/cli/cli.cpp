#include "cli.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <new>
#include <ostream>

#include "commands.h"
#include "holefill/errors.h"
#include "holefill/version.h"

namespace holefill::cli {
namespace {

constexpr const char* kDescription =
    "holefill " HOLEFILL_VERSION ": fill holes in triangle meshes (Wei, Wu & Pang 2010)";

constexpr const char* kExitCodes =
    "Meshes are read from .obj .off .ply .stl and written as .obj .off .ply.\n"
    "Exit codes: 0 ok, 1 some holes not filled (output written), 2 usage error, 3 bad input,\n"
    "4 output not written, 5 every hole filled but some patch intersects the mesh,\n"
    "6 internal error.";

// Everything the command line can hold, alive while CLI11 parses into it.
struct CommandLine {
  CLI::App app{kDescription, "holefill"};
  CLI::App* info = nullptr;
  CLI::App* fill = nullptr;
  CLI::App* help = nullptr;
  std::string info_input;
  std::string help_topic;
  FillArguments fill_arguments;
  bool quiet = false;

  CommandLine() {
    app.set_version_flag("--version", "holefill " HOLEFILL_VERSION);
    app.footer(kExitCodes);
    app.require_subcommand(1);
    app.fallthrough();  // -q also after the command's name
    app.add_flag("-q,--quiet", quiet,
                 "print no table on stdout (warnings and errors still go to stderr)");
    info = app.add_subcommand("info", "vertices, faces, components and a table of holes");
    info->add_option("MESH", info_input, "the mesh to describe")->required();
    fill = app.add_subcommand("fill", "fill holes, write the result, print a table");
    add_fill_options(*fill, fill_arguments);
    help = app.add_subcommand("help", "this text, or a command's options");
    help->add_option("COMMAND", help_topic, "info or fill")->check(CLI::IsMember({"info", "fill"}));
  }

  Verbosity verbosity() const { return quiet ? Verbosity::Quiet : Verbosity::Normal; }
};

int usage_error(const std::string& message, std::ostream& err) {
  err << "holefill: " << message << "\nRun 'holefill --help' or 'holefill COMMAND --help'.\n";
  return kUsage;
}

int dispatch(CommandLine& line, std::ostream& out, std::ostream& err) {
  const Streams streams{out, err, line.verbosity()};
  if (line.info->parsed()) return run_info(line.info_input, streams);
  if (line.fill->parsed()) {
    finish_fill_options(line.fill_arguments);
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

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CommandLine line;
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    line.app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      return line.app.exit(e, out, err);  // --help, --version
    }
    return usage_error(e.what(), err);
  }
  try {
    return dispatch(line, out, err);
  } catch (const UsageError& e) {
    return usage_error(e.what(), err);
  } catch (const FileError& e) {
    err << "holefill: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::bad_alloc&) {
    err << "holefill: out of memory\n";
    return kBadInput;
  } catch (const std::exception& e) {
    err << "holefill: internal error: " << e.what() << " (please report it)\n";
    return kInternalError;
  }
}

}  // namespace holefill::cli
