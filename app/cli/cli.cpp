#include "cli.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "holefill/errors.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/stats.h"
#include "report.h"

namespace holefill::cli {
namespace {

constexpr const char* kMainHelp = R"(holefill: fill holes in triangle meshes (Wei, Wu & Pang 2010)

usage:
  holefill info MESH              vertices, faces, components and a table of holes
  holefill fill MESH -o OUT [options]
                                  fill holes, write OUT (.obj .off .ply), print a table
  holefill help [COMMAND]         this text, or a command's options

Meshes are read from .obj .off .ply .stl.
Exit codes: 0 ok, 1 some holes not filled, 2 usage, 3 bad input, 4 write failed,
5 all filled but some patch intersects the mesh, 6 internal error.
)";

constexpr const char* kInfoHelp = R"(usage: holefill info MESH

Prints the mesh's vertex, face and component counts, and one row per hole (boundary loop):
its id (largest hole first), boundary edges, perimeter, and whether it is pinched (shares a
vertex with another loop).
)";

constexpr const char* kFillHelp = R"(usage: holefill fill MESH -o OUT [options]

  -o, --output OUT            where to write the result (.obj .off .ply); written atomically
  --weight maxmin|liepa|area  triangulation weight (default maxmin, the paper's)
  --fold-limit DEG            maxmin: a dihedral angle above DEG is minimised before the
                              smallest angle is maximised (default 45; 180 = the paper's order)
  --restricted-above N        holes with more than N boundary edges are triangulated over a
                              restricted set of chords (default 800; 0 = always the full
                              search, which takes at most 3000 edges)
  --tau T                     refinement density factor, > 0 (default 1.41421, sqrt 2)
  --remesh on|off             after refinement, flip and relax the patch toward valence 6
                              (not in the paper; default off)
  --smooth umbrella|fair      umbrella smoothing (the paper's, default) or fairing that
                              continues the surrounding curvature
  --fair-order 2|3            fairing: 2 bi-Laplacian (default), 3 tri-Laplacian
  --fair-weights cotangent|uniform
                              fairing: Laplacian weights (default cotangent)
  --smooth-iterations N       umbrella smoothing iterations, >= 0 (default 10)
  --smooth-step L             umbrella step lambda, in (0, 1] (default 0.5)
  --holes 0,3,5               fill only these hole ids (as `holefill info` lists them)
  --max-boundary N            fill only holes with at most N boundary edges
  --stage triangulate|refine|smooth
                              stop after this stage (default smooth)
  --report FILE.json          write per-hole statistics as JSON
)";

struct UsageError {
  std::string message;
};

double parse_number(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value)) {
    throw UsageError{option + " needs a number, got '" + text + "'"};
  }
  return value;
}

long parse_integer(const std::string& option, const std::string& text) {
  const double value = parse_number(option, text);
  if (value != static_cast<double>(static_cast<long>(value))) {
    throw UsageError{option + " needs a whole number, got '" + text + "'"};
  }
  return static_cast<long>(value);
}

std::vector<int> parse_id_list(const std::string& text) {
  std::vector<int> ids;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const long id = parse_integer("--holes", item);
    if (id < 0) throw UsageError{"--holes takes ids >= 0, got '" + item + "'"};
    ids.push_back(static_cast<int>(id));
  }
  if (ids.empty()) throw UsageError{"--holes needs a list of ids, e.g. --holes 0,2"};
  return ids;
}

Stage parse_stage(const std::string& text) {
  if (text == "triangulate") return Stage::Triangulated;
  if (text == "refine") return Stage::Refined;
  if (text == "smooth") return Stage::Smoothed;
  throw UsageError{"--stage takes triangulate, refine or smooth, got '" + text + "'"};
}

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

Mesh load_and_warn(const std::string& path, std::ostream& err) {
  LoadReport report;
  Mesh mesh = load_mesh(path, &report);
  for (const auto& warning : report.warnings)
    err << "holefill: " << path << ": " << warning << "\n";
  return mesh;
}

int run_info(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.size() != 1) throw UsageError{"info takes exactly one MESH"};
  const Mesh mesh = load_and_warn(args[0], err);
  const auto holes = find_holes(mesh);
  out << args[0] << ": " << mesh.n_vertices() << " vertices, " << mesh.n_faces() << " faces, "
      << connected_components(mesh) << " components, " << holes.size() << " holes\n";
  if (holes.empty()) return kOk;
  out << "  hole  boundary_edges   perimeter  note\n";
  for (const auto& hole : holes) {
    out << std::setw(6) << hole.id << std::setw(16) << hole.size() << std::setw(12)
        << format("%.6g", hole.perimeter) << "  " << (hole.pinched ? "pinched" : "") << "\n";
  }
  return kOk;
}

int run_fill(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::string input, output, report_path;
  FillOptions options;
  HoleSelection selection;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError{arg + " needs a value"};
      return args[++i];
    };
    if (arg == "-o" || arg == "--output") {
      output = value();
    } else if (arg == "--weight") {
      const std::string& text = value();
      if (!parse_weight(text, options.triangulate.weight)) {
        throw UsageError{"--weight takes maxmin, liepa or area, got '" + text + "'"};
      }
    } else if (arg == "--fold-limit") {
      const double degrees = parse_number(arg, value());
      if (!(degrees > 0.0 && degrees <= 180.0))
        throw UsageError{"--fold-limit must be in (0, 180]"};
      options.triangulate.fold_limit = degrees * M_PI / 180.0;
    } else if (arg == "--restricted-above") {
      const long n = parse_integer(arg, value());
      if (n < 0) throw UsageError{"--restricted-above must be 0 (never) or a boundary edge count"};
      options.triangulate.restricted.above_edges = static_cast<std::size_t>(n);
    } else if (arg == "--tau") {
      options.refine.tau = parse_number(arg, value());
      if (options.refine.tau <= 0.0) throw UsageError{"--tau must be greater than 0"};
    } else if (arg == "--remesh") {
      const std::string& text = value();
      if (text != "on" && text != "off") {
        throw UsageError{"--remesh takes on or off, got '" + text + "'"};
      }
      options.refine.remesh = text == "on";
    } else if (arg == "--smooth") {
      const std::string& text = value();
      if (text == "umbrella") {
        options.smooth.method = SmoothMethod::Umbrella;
      } else if (text == "fair") {
        options.smooth.method = SmoothMethod::Fair;
      } else {
        throw UsageError{"--smooth takes umbrella or fair, got '" + text + "'"};
      }
    } else if (arg == "--fair-order") {
      const long order = parse_integer(arg, value());
      if (order != 2 && order != 3) throw UsageError{"--fair-order takes 2 or 3"};
      options.smooth.fair.order = static_cast<int>(order);
    } else if (arg == "--fair-weights") {
      const std::string& text = value();
      if (text != "cotangent" && text != "uniform") {
        throw UsageError{"--fair-weights takes cotangent or uniform, got '" + text + "'"};
      }
      options.smooth.fair.cotangent_weights = text == "cotangent";
    } else if (arg == "--smooth-iterations") {
      const long n = parse_integer(arg, value());
      if (n < 0 || n > 1'000'000) throw UsageError{"--smooth-iterations must be in 0..1000000"};
      options.smooth.iterations = static_cast<int>(n);
    } else if (arg == "--smooth-step") {
      options.smooth.step = parse_number(arg, value());
      if (!(options.smooth.step > 0.0 && options.smooth.step <= 1.0)) {
        throw UsageError{"--smooth-step must be in (0, 1]"};
      }
    } else if (arg == "--holes") {
      selection.hole_ids = parse_id_list(value());
    } else if (arg == "--max-boundary") {
      const long n = parse_integer(arg, value());
      if (n < 3) throw UsageError{"--max-boundary must be at least 3"};
      selection.max_boundary_edges = static_cast<std::size_t>(n);
    } else if (arg == "--stage") {
      options.last_stage = parse_stage(value());
    } else if (arg == "--report") {
      report_path = value();
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError{"unknown option '" + arg + "'"};
    } else if (input.empty()) {
      input = arg;
    } else {
      throw UsageError{"unexpected argument '" + arg + "'"};
    }
  }
  if (input.empty()) throw UsageError{"fill needs a MESH"};
  if (output.empty()) throw UsageError{"fill needs -o OUT"};
  {
    std::string ext = std::filesystem::path(output).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const auto& writable = writable_extensions();
    if (std::find(writable.begin(), writable.end(), ext) == writable.end()) {
      throw UsageError{"-o " + output + ": cannot write '" + ext +
                       "' files (use .obj, .off or .ply)"};
    }
  }

  Mesh mesh = load_and_warn(input, err);
  const auto holes = find_holes(mesh);
  for (const int id : selection.hole_ids) {
    if (id >= static_cast<int>(holes.size())) {
      throw UsageError{"--holes: " + input + " has no hole " + std::to_string(id) + " (it has " +
                       std::to_string(holes.size()) + ")"};
    }
  }
  ReportInput report;
  report.input_path = input;
  report.output_path = output;
  report.options = &options;
  report.vertices_before = mesh.n_vertices();
  report.faces_before = mesh.n_faces();
  report.holes_before = holes.size();

  const auto fills = fill_holes(mesh, holes, options, selection);
  report.vertices_after = mesh.n_vertices();
  report.faces_after = mesh.n_faces();
  report.holes_after = find_holes(mesh).size();
  report.fills = &fills;

  out << "  hole  boundary  stage          new_v   new_f  min_angle  max_dihedral  intersect"
         "   seconds\n";
  std::size_t filled = 0, intersecting = 0;
  for (const auto& fill : fills) {
    const auto& s = fill.stats;
    const double seconds = fill.times.triangulate_seconds + fill.times.refine_seconds +
                           fill.times.smooth_seconds + fill.times.check_seconds;
    out << std::setw(6) << fill.hole_id << std::setw(10) << fill.boundary_edges << "  " << std::left
        << std::setw(13) << (fill.failed() ? "FAILED" : to_string(fill.stage())) << std::right
        << std::setw(7) << s.new_vertices << std::setw(8) << s.new_faces << std::setw(11)
        << format("%.2f", s.min_angle_deg) << std::setw(14) << format("%.2f", s.max_dihedral_deg)
        << std::setw(11) << fill.self_intersections << std::setw(10) << format("%.4f", seconds)
        << "\n";
    if (!fill.failed()) ++filled;
    if (fill.self_intersections > 0) {
      ++intersecting;
      err << "holefill: " << input << ": hole " << fill.hole_id
          << ": the patch intersects the mesh (" << fill.self_intersections
          << " pairs of triangles)\n";
    }
    if (!fill.refinement_note.empty()) {
      err << "holefill: " << input << ": hole " << fill.hole_id << ": " << fill.refinement_note
          << "\n";
    }
    if (!fill.smoothing_note.empty()) {
      err << "holefill: " << input << ": hole " << fill.hole_id << ": " << fill.smoothing_note
          << "\n";
    }
    if (fill.failed()) {
      err << "holefill: " << input << ": hole " << fill.hole_id << " not filled: " << fill.failure
          << "\n";
    }
  }
  out << input << ": filled " << filled << " of " << fills.size() << " selected holes ("
      << holes.size() << " in all); " << report.holes_after << " holes remain";
  if (intersecting) out << "; " << intersecting << " patches intersect the mesh";
  out << "\n";

  try {
    save_mesh(mesh, output);
  } catch (const FileError& e) {
    err << "holefill: " << e.what() << "\n";
    return kWriteFailed;
  }
  if (!report_path.empty()) {
    std::ostringstream json;
    write_json_report(report, json);
    const std::string temp = report_path + ".partial";
    std::ofstream file(temp, std::ios::binary);
    file << json.str();
    file.close();
    std::error_code ec;
    if (!file || (std::filesystem::rename(temp, report_path, ec), ec)) {
      std::filesystem::remove(temp, ec);
      err << "holefill: " << report_path << ": the report could not be written\n";
      return kWriteFailed;
    }
  }
  if (filled != fills.size()) return kSomeHolesNotFilled;
  return intersecting ? kPatchesIntersect : kOk;
}

}  // namespace

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const std::string command = args.empty() ? "help" : args[0];
  const std::vector<std::string> rest(args.begin() + (args.empty() ? 0 : 1), args.end());
  const bool wants_help = std::find(rest.begin(), rest.end(), "--help") != rest.end() ||
                          std::find(rest.begin(), rest.end(), "-h") != rest.end();
  try {
    if (command == "help" || command == "--help" || command == "-h") {
      const std::string topic = rest.empty() ? "" : rest[0];
      out << (topic == "info" ? kInfoHelp : topic == "fill" ? kFillHelp : kMainHelp);
      return kOk;
    }
    if (command == "info") {
      if (wants_help) return out << kInfoHelp, kOk;
      return run_info(rest, out, err);
    }
    if (command == "fill") {
      if (wants_help) return out << kFillHelp, kOk;
      return run_fill(rest, out, err);
    }
    throw UsageError{"unknown command '" + command + "'"};
  } catch (const UsageError& e) {
    err << "holefill: " << e.message << "\n(see 'holefill help')\n";
    return kUsage;
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
