#include "command_line.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <stdexcept>

#include "holefill/version.h"

namespace holefill::viewer {
namespace {

constexpr const char* kScripted = "Scripted mode (for automation and documentation)";

Stage parse_stage(const std::string& name) {
  if (name == "triangulate") return Stage::Triangulated;
  if (name == "refine") return Stage::Refined;
  if (name == "smooth") return Stage::Smoothed;
  throw std::invalid_argument("unknown stage '" + name + "' (triangulate, refine or smooth)");
}

// What the command line sets once parsed, before it is checked and turned into a CommandLine.
struct Parsed {
  CommandLine command;
  std::vector<std::string> stages;
  std::string size;
};

// The viewer's options, writing into `parsed`. Defaults shown in the help come from CommandLine.
void add_options(CLI::App& app, Parsed& parsed) {
  CommandLine& c = parsed.command;
  app.set_version_flag("--version", "holefill-viewer " HOLEFILL_VERSION);
  app.add_option("MESH", c.mesh, "the mesh to open (default: the bundled bunny)");
  app.add_option("--select-hole", c.select_hole,
                 "select hole K (0 is the largest) with its islands")
      ->type_name("K")
      ->group(kScripted);
  app.add_option("--add-hole", c.add_holes,
                 "add loop K to the selection, as shift-click does\n(repeatable; two loops: --run "
                 "bridges them)")
      ->type_name("K")
      ->allow_extra_args(false)
      ->group(kScripted);
  app.add_option("--run", parsed.stages, "run these stages on the selected hole, in order")
      ->type_name("triangulate,refine,smooth")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->group(kScripted);
  app.add_flag("--fill-all", c.fill_all, "fill every hole")->group(kScripted);
  app.add_flag("--remesh", c.remesh, "refine with the remeshing pass (toward valence 6)")
      ->group(kScripted);
  app.add_flag("--fair", c.fair, "smooth by fairing instead of the umbrella operator")
      ->group(kScripted);
  app.add_option("--fair-order", c.fair_order, "fairing's order (implies --fair)")
      ->check(CLI::IsMember({2, 3}))
      ->capture_default_str()
      ->group(kScripted);
  app.add_flag("--compare", c.compare, "show liepa (left) vs maxmin (right) on the hole")
      ->group(kScripted);
  app.add_flag("--compare-triangulation-only", c.compare_triangulation_only,
               "compare the triangulation stage only")
      ->group(kScripted);
  app.add_flag("--compare-smoothing", c.compare_smoothing,
               "show umbrella (left) vs fair (right) instead")
      ->group(kScripted);
  app.add_flag("--compare-features", c.compare_features,
               "show the paper's fill (left) vs sharp features continued (right) instead")
      ->group(kScripted);
  app.add_option("--feature-angle", c.feature_angle,
                 "sharp features: the dihedral angle above which an edge is one\n(degrees; 0 off)")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str()
      ->group(kScripted);
  app.add_option("--size", parsed.size, "window size")
      ->type_name("WxH")
      ->default_str(std::to_string(c.width) + "x" + std::to_string(c.height))
      ->group(kScripted);
  app.add_option("--save", c.save,
                 "after the above, save the mesh (.obj .off .ply .stl)\nand exit, with no window "
                 "unless --screenshot")
      ->type_name("OUT")
      ->group(kScripted);
  app.add_option("--screenshot", c.screenshot, "render, save the window as PNG and exit")
      ->type_name("OUT.png")
      ->group(kScripted);
  app.add_option("--state-file", c.state_file,
                 "keep the window's state in this file (frames, keys received,\nidle, busy, "
                 "question, title, message) for automation")
      ->type_name("PATH")
      ->group(kScripted);
  app.add_option("--ui-scale", c.ui_scale,
                 "text and panel scale (default: the monitor's;\nCtrl +/- change it)")
      ->type_name("S")
      ->check(CLI::Range(0.5f, 4.0f));
  app.add_option("--threads", c.threads,
                 "threads that open, prepare and fill meshes (0: every core\nthis process may "
                 "run on, below the window's priority);\nthe result is the same whatever the "
                 "number")
      ->type_name("N")
      ->check(CLI::Range(0u, 4096u))
      ->capture_default_str();
  app.add_option("--frames", c.frames,
                 "with --screenshot: render N frames (turning the view\na little each) and print "
                 "the mean frame time: the first\nhalf whole, the second as a drag draws them "
                 "(a big\nmesh as its coarse proxy, which the screenshot shows)")
      ->type_name("N")
      ->check(CLI::Range(4, 1'000'000))
      ->group(kScripted);
}

// "WxH" as a window size, at least 64 pixels each way.
void parse_size(const std::string& size, CommandLine& c) {
  const auto x = size.find('x');
  std::size_t used_w = 0, used_h = 0;
  try {
    if (x == std::string::npos) throw std::invalid_argument(size);
    c.width = std::stoi(size.substr(0, x), &used_w);
    c.height = std::stoi(size.substr(x + 1), &used_h);
  } catch (const std::exception&) {
    used_w = 0;
  }
  if (x == std::string::npos || used_w != x || used_h != size.size() - x - 1) {
    throw std::invalid_argument("--size needs WxH, got '" + size + "'");
  }
  if (c.width < 64 || c.height < 64) throw std::invalid_argument("--size is too small");
}

// The options that imply others, and the combinations scripted mode cannot run.
void complete_and_check(const CLI::App& app, Parsed& parsed) {
  CommandLine& c = parsed.command;
  for (const auto& name : parsed.stages) c.run.push_back(parse_stage(name));
  if (!parsed.size.empty()) parse_size(parsed.size, c);
  c.fair = c.fair || app.count("--fair-order") > 0;
  c.compare =
      c.compare || c.compare_triangulation_only || c.compare_smoothing || c.compare_features;
  if (c.compare_smoothing && c.compare_features) {
    throw std::invalid_argument("--compare-smoothing and --compare-features exclude each other");
  }
  c.report_frame_time = app.count("--frames") > 0;
  if (!c.run.empty() && !c.select_hole) throw std::invalid_argument("--run needs --select-hole");
  if (c.report_frame_time && c.screenshot.empty()) {
    throw std::invalid_argument("--frames needs --screenshot");
  }
  if (!c.add_holes.empty() && !c.select_hole) {
    throw std::invalid_argument("--add-hole needs --select-hole");
  }
  if (c.compare && !c.select_hole) throw std::invalid_argument("--compare needs --select-hole");
}

}  // namespace

std::string usage() {
  CLI::App app("Opens MESH (OBJ, OFF, PLY, STL) in a window; drop a file on it to open another.",
               "holefill-viewer");
  Parsed parsed;
  add_options(app, parsed);
  return app.help();
}

CommandLine parse_command_line(const std::vector<std::string>& arguments) {
  CLI::App app;
  Parsed parsed;
  add_options(app, parsed);
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11: last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    parsed.command.help = true;
    return parsed.command;
  } catch (const CLI::CallForVersion&) {
    parsed.command.version = true;
    return parsed.command;
  } catch (const CLI::ParseError& error) {
    throw std::invalid_argument(error.what());
  }
  complete_and_check(app, parsed);
  return parsed.command;
}

std::string version() { return "holefill-viewer " HOLEFILL_VERSION; }

std::filesystem::path default_mesh_path(const std::filesystem::path& executable) {
  // The build tree's executable sits three folders below the source tree (build/app/viewer); an
  // installed one finds share/holefill beside its bin/.
  const std::filesystem::path folder = executable.parent_path();
  std::vector<std::filesystem::path> candidates{folder / "../share/holefill/assets/bunny.obj"};
  std::filesystem::path up = folder;
  for (int level = 0; level < 4 && !up.empty(); ++level, up = up.parent_path()) {
    candidates.push_back(up / "assets" / "bunny.obj");
  }
  const auto found = std::find_if(candidates.begin(), candidates.end(),
                                  [](const auto& path) { return std::filesystem::exists(path); });
  return found != candidates.end() ? found->lexically_normal() : candidates.back();
}

}  // namespace holefill::viewer
