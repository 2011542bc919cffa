#include "command_line.h"

#include <sstream>
#include <stdexcept>

namespace holefill::viewer {
namespace {

Stage parse_stage(const std::string& name) {
  if (name == "triangulate") return Stage::Triangulated;
  if (name == "refine") return Stage::Refined;
  if (name == "smooth") return Stage::Smoothed;
  throw std::invalid_argument("unknown stage '" + name + "' (triangulate, refine or smooth)");
}

int parse_int(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size())
    throw std::invalid_argument(option + " needs a number, got '" + text + "'");
  return value;
}

}  // namespace

const char* usage() {
  return "usage: holefill-viewer [MESH] [options]\n"
         "Opens MESH (OBJ, OFF, PLY, STL; default: the bundled bunny) in a window.\n"
         "\n"
         "Scripted mode (for automation and documentation):\n"
         "  --select-hole K                 select hole K (0 is the largest) with its islands\n"
         "  --add-hole K                    add loop K to the selection, as shift-click does\n"
         "                                  (repeatable; two loops: --run bridges them)\n"
         "  --run triangulate,refine,smooth run these stages on the selected hole\n"
         "  --fill-all                      fill every hole\n"
         "  --remesh                        refine with the remeshing pass (toward valence 6)\n"
         "  --fair                          smooth by fairing instead of the umbrella operator\n"
         "  --fair-order 2|3                fairing's order (default 2; implies --fair)\n"
         "  --compare                       show liepa (left) vs maxmin (right) on the hole\n"
         "  --compare-triangulation-only    compare the triangulation stage only\n"
         "  --compare-smoothing             show umbrella (left) vs fair (right) instead\n"
         "  --size WxH                      window size (default 1280x800)\n"
         "  --save OUT                      after the above, save the mesh (.obj .off .ply .stl)\n"
         "                                  and exit, with no window unless --screenshot\n"
         "  --screenshot OUT.png            render, save the window as PNG and exit\n"
         "  --frames N                      with --screenshot: render N frames (turning the\n"
         "                                  view a little each) and print the mean frame time\n"
         "  --help                          print this text\n";
}

CommandLine parse_command_line(const std::vector<std::string>& arguments) {
  CommandLine command;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& arg = arguments[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= arguments.size()) throw std::invalid_argument(arg + " needs a value");
      return arguments[++i];
    };
    if (arg == "--help" || arg == "-h") {
      command.help = true;
    } else if (arg == "--select-hole") {
      command.select_hole = parse_int(value(), arg);
    } else if (arg == "--add-hole") {
      command.add_holes.push_back(parse_int(value(), arg));
    } else if (arg == "--run") {
      std::stringstream stages(value());
      for (std::string name; std::getline(stages, name, ',');)
        command.run.push_back(parse_stage(name));
    } else if (arg == "--fill-all") {
      command.fill_all = true;
    } else if (arg == "--remesh") {
      command.remesh = true;
    } else if (arg == "--fair") {
      command.fair = true;
    } else if (arg == "--fair-order") {
      command.fair = true;
      command.fair_order = parse_int(value(), arg);
      if (command.fair_order != 2 && command.fair_order != 3)
        throw std::invalid_argument("--fair-order takes 2 or 3");
    } else if (arg == "--compare") {
      command.compare = true;
    } else if (arg == "--compare-triangulation-only") {
      command.compare = true;
      command.compare_triangulation_only = true;
    } else if (arg == "--compare-smoothing") {
      command.compare = true;
      command.compare_smoothing = true;
    } else if (arg == "--size") {
      const std::string& size = value();
      const auto x = size.find('x');
      if (x == std::string::npos)
        throw std::invalid_argument("--size needs WxH, got '" + size + "'");
      command.width = parse_int(size.substr(0, x), arg);
      command.height = parse_int(size.substr(x + 1), arg);
      if (command.width < 64 || command.height < 64)
        throw std::invalid_argument("--size is too small");
    } else if (arg == "--frames") {
      command.frames = parse_int(value(), arg);
      command.report_frame_time = true;
      if (command.frames < 4) throw std::invalid_argument("--frames needs at least 4");
    } else if (arg == "--save") {
      command.save = value();
    } else if (arg == "--screenshot") {
      command.screenshot = value();
    } else if (!arg.empty() && arg[0] == '-') {
      throw std::invalid_argument("unknown option " + arg);
    } else if (command.mesh.empty()) {
      command.mesh = arg;
    } else {
      throw std::invalid_argument("only one mesh can be opened, got '" + arg + "' too");
    }
  }
  if (!command.run.empty() && !command.select_hole) {
    throw std::invalid_argument("--run needs --select-hole");
  }
  if (command.report_frame_time && command.screenshot.empty()) {
    throw std::invalid_argument("--frames needs --screenshot");
  }
  if (!command.add_holes.empty() && !command.select_hole) {
    throw std::invalid_argument("--add-hole needs --select-hole");
  }
  if (command.compare && !command.select_hole) {
    throw std::invalid_argument("--compare needs --select-hole");
  }
  return command;
}

std::filesystem::path default_mesh_path(const std::filesystem::path& executable) {
  const std::filesystem::path compiled_in =
      std::filesystem::path(HOLEFILL_ASSETS_DIR) / "bunny.obj";
  if (std::filesystem::exists(compiled_in)) return compiled_in;
  std::filesystem::path folder = executable.parent_path();
  for (int up = 0; up < 4 && !folder.empty(); ++up, folder = folder.parent_path()) {
    const auto candidate = folder / "assets" / "bunny.obj";
    if (std::filesystem::exists(candidate)) return candidate;
  }
  return compiled_in;
}

}  // namespace holefill::viewer
