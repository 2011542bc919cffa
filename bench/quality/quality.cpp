// holefill-quality: how close and how well-shaped are the patches? Cuts holes of chosen sizes
// out of closed meshes (generated shapes and the closed bunny), fills them with every
// combination of triangulation weight and smoothing (and with CGAL's
// triangulate_refine_and_fair_hole when built with CGAL), measures each patch against the
// surface that was cut away, and prints one Markdown table. See README.md beside this file.
//
//   holefill-quality [--assets DIR] [--meshes a,b] [--weights a,b] [--smooth a,b]
//                    [--cut R,R,...]... [--seed N] [--write DIR]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench_text.h"
#include "cut_holes.h"
#include "holefill/errors.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "measure.h"
#include "shapes.h"
#ifdef HOLEFILL_QUALITY_WITH_CGAL
#include "cgal_bridge.h"
#endif

namespace holefill::quality {
namespace {

constexpr const char* kUsage = R"(usage: holefill-quality [options]

  --assets DIR         where bunny_closed.obj is (default: the source tree's assets/)
  --meshes a,b         sphere, ellipsoid, blob, torus, bunny (default: all)
  --weights a,b        maxmin, liepa, area (default: all three; the summaries show the first)
  --smooth a,b         umbrella, fair-cot-2, fair-uniform-2, fair-cot-3, fair-uniform-3,
                       any of these five followed by +remesh (the refined patch remeshed
                       toward valence 6 first, e.g. fair-cot-2+remesh),
                       cgal (CGAL's whole hole filling), cgal-fair (our triangulation and
                       refinement, CGAL's fairing), truth (the cut faces themselves)
                       (default: all that this build has)
  --cut R,R,...        one cut with a hole of each radius, in mean edge lengths; repeatable
                       (default: --cut 3,3,3 --cut 7)
  --seed N             seed for the hole centres (default 1)
  --write DIR          also write every filled mesh there as OBJ
)";

struct Shape {
  std::string name;
  std::function<Mesh()> make;
};

std::vector<Shape> shapes(const std::filesystem::path& assets) {
  return {
      {"sphere", [] { return make_icosphere(4); }},
      {"ellipsoid",
       [] {
         return make_star_shape(
             4, [](const Point&) { return 1.0; }, Point(1.6, 1.0, 0.6));
       }},
      {"blob",
       [] {
         return make_star_shape(
             4,
             [](const Point& p) {
               return 1.0 + 0.2 * std::sin(3.0 * p[0]) * std::sin(3.0 * p[1] + 1.0) *
                                std::cos(2.0 * p[2]);
             },
             Point(1.0, 1.0, 1.0));
       }},
      {"torus", [] { return make_torus(1.0, 0.4, 72, 28); }},
      {"bunny", [assets] { return load_mesh(assets / "bunny_closed.obj"); }},
  };
}

// How a cut mesh is filled: our pipeline with one weight and one smoothing, CGAL's, or the
// truth itself (the removed faces, as a reference row).
struct Method {
  std::string weight;
  std::string smoothing;
  FillOptions options;
};

// A smoothing name, optionally followed by "+remesh" (the refined patch remeshed first).
std::optional<FillOptions> smoothing_options(std::string name) {
  FillOptions options;
  const std::string remesh_suffix = "+remesh";
  if (name.size() > remesh_suffix.size() &&
      name.compare(name.size() - remesh_suffix.size(), remesh_suffix.size(), remesh_suffix) == 0) {
    options.refine.remesh = true;
    name.resize(name.size() - remesh_suffix.size());
  }
  if (name == "umbrella") return options;
  if (name.rfind("fair-cot-", 0) == 0 || name.rfind("fair-uniform-", 0) == 0) {
    options.smooth.method = SmoothMethod::Fair;
    options.smooth.fair.cotangent_weights = name.rfind("fair-cot-", 0) == 0;
    options.smooth.fair.order = name.back() - '0';
    if (options.smooth.fair.order == 2 || options.smooth.fair.order == 3) return options;
  }
  return std::nullopt;
}

std::string hole_sizes(const std::vector<Hole>& holes) {
  std::ostringstream text;
  for (std::size_t i = 0; i < holes.size(); ++i) text << (i ? "/" : "") << holes[i].size();
  return text.str();
}

// One line of the results: a cut mesh filled one way, measured.
struct Row {
  std::string mesh, holes, weight, smoothing;
  Quality quality;
  std::string notes;
};

void print_table(const std::vector<Row>& rows) {
  std::cout << "| mesh | holes (boundary edges) | weight | smoothing | new V / F "
               "| mean dist % | max dist % | min∠ p5 ° | min∠ ° | valence 6 % | edge ratio "
               "| boundary dihedral mean ° | boundary dihedral max ° | max dihedral ° | notes |\n"
               "|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const auto& row : rows) {
    const Quality& q = row.quality;
    std::cout << "| " << row.mesh << " | " << row.holes << " | " << row.weight << " | "
              << row.smoothing << " | " << q.new_vertices << " / " << q.faces << " | "
              << format(100.0 * q.mean_distance, 3) << " | " << format(100.0 * q.max_distance, 3)
              << " | " << format(q.min_angle_p5, 1) << " | " << format(q.min_angle, 1) << " | "
              << format(100.0 * q.valence6_share, 0) << " | " << format(q.edge_length_ratio, 2)
              << " | " << format(q.mean_boundary_dihedral, 1) << " | "
              << format(q.max_boundary_dihedral, 1) << " | " << format(q.max_dihedral, 1) << " | "
              << row.notes << " |\n";
  }
}

// One measure side by side: a line per cut mesh, a column per way of filling (the first
// weight's smoothings, then CGAL's), the best value of each line in bold.
void print_pivot(const std::vector<Row>& rows, const std::string& weight, const std::string& title,
                 double (*value)(const Quality&), bool lower_is_better, int decimals) {
  std::vector<std::string> columns, cases;
  for (const auto& row : rows) {
    const bool ours = row.weight == weight, cgal = row.weight == "CGAL";
    if ((ours || cgal) &&
        std::find(columns.begin(), columns.end(), row.smoothing) == columns.end()) {
      columns.push_back(row.smoothing);
    }
    const std::string label = row.mesh + " " + row.holes;
    if (std::find(cases.begin(), cases.end(), label) == cases.end()) cases.push_back(label);
  }
  std::cout << "**" << title << "** (triangulation weight " << weight << ")\n\n| mesh, holes |";
  for (const auto& column : columns) std::cout << " " << column << " |";
  std::cout << "\n|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) std::cout << "---:|";
  std::cout << "\n";
  for (const auto& label : cases) {
    std::vector<double> values(columns.size(), std::nan(""));
    for (const auto& row : rows) {
      if (row.mesh + " " + row.holes != label || (row.weight != weight && row.weight != "CGAL")) {
        continue;
      }
      const auto at = std::find(columns.begin(), columns.end(), row.smoothing) - columns.begin();
      values[at] = value(row.quality);
    }
    double best = lower_is_better ? INFINITY : -INFINITY;
    for (const double v : values) {
      if (!std::isnan(v)) best = lower_is_better ? std::min(best, v) : std::max(best, v);
    }
    // Bold every value that prints like the best one: ties at the printed precision.
    const std::string best_text = format(best, decimals);
    std::cout << "| " << label << " |";
    for (const double v : values) {
      const std::string text = format(v, decimals);
      std::cout << " " << (text == best_text ? "**" + text + "**" : text) << " |";
    }
    std::cout << "\n";
  }
  std::cout << "\n";
}

// The truth's own measures: the removed faces in the closed mesh, as if they were the patch.
std::vector<FilledHole> truth_patches(const Mesh& closed, const CutMesh& cut,
                                      const std::vector<Hole>& loops) {
  std::vector<FilledHole> patches;
  for (const auto& loop : loops) {
    for (const auto& hole : cut.holes) {
      bool owns = false;
      for (const auto f : hole.removed_faces) {
        for (const auto v : closed.fv_range(f)) owns = owns || v == loop.vertices[0];
      }
      if (!owns) continue;
      patches.push_back({loop.vertices, hole.removed_faces, hole.inner_vertices});
    }
  }
  return patches;
}

// What the command line asks for, with the defaults filled in.
struct Arguments {
  std::filesystem::path assets = HOLEFILL_QUALITY_ASSETS_DIR;
  std::vector<std::string> mesh_names, weight_names{"maxmin", "liepa", "area"}, smoothing_names;
  std::vector<std::vector<double>> cuts;
  unsigned seed = 1;
  std::optional<std::filesystem::path> write_dir;
  bool help = false;  // --help: print the usage and stop (later arguments are not read)

  bool wanted(const std::string& smoothing) const {
    return std::find(smoothing_names.begin(), smoothing_names.end(), smoothing) !=
           smoothing_names.end();
  }
};

// Throws UsageError on an unknown argument or a missing value.
Arguments parse_arguments(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError{arg + " needs a value"};
      return argv[++i];
    };
    if (arg == "--assets") {
      a.assets = value();
    } else if (arg == "--meshes") {
      a.mesh_names = split(value());
    } else if (arg == "--weights") {
      a.weight_names = split(value());
    } else if (arg == "--smooth") {
      a.smoothing_names = split(value());
    } else if (arg == "--cut") {
      std::vector<double> radii;
      for (const auto& r : split(value())) radii.push_back(std::stod(r));
      a.cuts.push_back(radii);
    } else if (arg == "--seed") {
      a.seed = static_cast<unsigned>(std::stoul(value()));
    } else if (arg == "--write") {
      a.write_dir = value();
    } else if (arg == "-h" || arg == "--help") {
      a.help = true;
      return a;
    } else {
      throw UsageError{"unknown argument '" + arg + "'"};
    }
  }
  if (a.cuts.empty()) a.cuts = {{3, 3, 3}, {7}};
  if (a.smoothing_names.empty()) {
    a.smoothing_names = {"umbrella",          "fair-cot-2",       "fair-uniform-2",
                         "fair-cot-3",        "fair-uniform-3",   "umbrella+remesh",
                         "fair-cot-2+remesh", "fair-cot-3+remesh"};
#ifdef HOLEFILL_QUALITY_WITH_CGAL
    a.smoothing_names.push_back("cgal-fair");
    a.smoothing_names.push_back("cgal");
#endif
    a.smoothing_names.push_back("truth");
  }
  return a;
}

// The library's fills to run: each smoothing with each weight (cgal-fair stops after refinement;
// cgal and truth are not the library's). Throws UsageError on an unknown name.
std::vector<Method> methods_of(const Arguments& a) {
  std::vector<Method> methods;
  for (const auto& smoothing : a.smoothing_names) {
    if (smoothing == "cgal-fair") {
#ifndef HOLEFILL_QUALITY_WITH_CGAL
      throw UsageError{"this build has no CGAL"};
#endif
      for (const auto& weight : a.weight_names) {
        FillOptions options;
        options.last_stage = Stage::Refined;
        if (!parse_weight(weight, options.triangulate.weight)) {
          throw UsageError{"unknown weight '" + weight + "'"};
        }
        methods.push_back({weight, smoothing, options});
      }
      continue;
    }
    if (smoothing == "cgal" || smoothing == "truth") {
#ifndef HOLEFILL_QUALITY_WITH_CGAL
      if (smoothing == "cgal") throw UsageError{"this build has no CGAL"};
#endif
      continue;
    }
    auto options = smoothing_options(smoothing);
    if (!options) throw UsageError{"unknown smoothing '" + smoothing + "'"};
    for (const auto& weight : a.weight_names) {
      if (!parse_weight(weight, options->triangulate.weight)) {
        throw UsageError{"unknown weight '" + weight + "'"};
      }
      methods.push_back({weight, smoothing, *options});
    }
  }
  return methods;
}

// Fills the holes of one cut of `shape` with every method (and CGAL, and the truth, when asked),
// appending a row per fill to `rows` and writing each filled mesh when --write asks.
void measure_cut(const Shape& shape, const Mesh& closed, const Truth& truth, const CutMesh& cut,
                 const Arguments& a, const std::vector<Method>& methods, std::vector<Row>& rows) {
  const auto loops = find_holes(cut.mesh);
  const std::string sizes = hole_sizes(loops);
  auto write = [&](const Mesh& mesh, const std::string& label) {
    if (!a.write_dir) return;
    std::string name = shape.name + "-" + sizes + "-" + label + ".obj";
    std::replace(name.begin(), name.end(), '/', '_');
    save_mesh(mesh, *a.write_dir / name);
  };
  for (const auto& method : methods) {
    Mesh mesh = cut.mesh;
    const auto fills = fill_holes(mesh, loops, method.options);
    std::vector<FilledHole> patches;
    std::size_t failed = 0, fell_back = 0;
    for (const auto& fill : fills) {
      failed += fill.failed();
      fell_back += !fill.smoothing_note.empty();
      patches.push_back({fill.patch.boundary, fill.patch.faces, fill.patch.new_vertices});
    }
    std::string notes;
#ifdef HOLEFILL_QUALITY_WITH_CGAL
    if (method.smoothing == "cgal-fair" && !fair_with_cgal(mesh, patches)) {
      notes += "CGAL fairing failed ";
    }
#endif
    if (failed) notes += std::to_string(failed) + " not filled ";
    if (fell_back) notes += std::to_string(fell_back) + " fell back to umbrella";
    rows.push_back(
        {shape.name, sizes, method.weight, method.smoothing, measure(mesh, patches, truth), notes});
    write(mesh, method.weight + "-" + method.smoothing);
  }
#ifdef HOLEFILL_QUALITY_WITH_CGAL
  if (a.wanted("cgal")) {
    std::size_t unfaired = 0;
    std::vector<FilledHole> patches;
    const Mesh filled = fill_with_cgal(cut.mesh, loops, patches, unfaired);
    rows.push_back({shape.name, sizes, "CGAL", "CGAL", measure(filled, patches, truth),
                    unfaired ? std::to_string(unfaired) + " not faired" : ""});
    write(filled, "cgal");
  }
#endif
  if (a.wanted("truth")) {
    rows.push_back({shape.name, sizes, "–", "truth (cut faces)",
                    measure(closed, truth_patches(closed, cut, loops), truth), ""});
  }
}

// The summaries (the distance for every weight, the rest for the first) and the whole table.
void print_results(const std::vector<Row>& rows, const std::vector<std::string>& weight_names) {
  const std::string& first_weight = weight_names.front();
  for (const auto& weight : weight_names) {
    print_pivot(
        rows, weight, "Mean distance to the truth, % of the bounding-box diagonal",
        [](const Quality& q) { return 100.0 * q.mean_distance; }, true, 3);
  }
  print_pivot(
      rows, first_weight, "5th percentile of the triangles' smallest angle, degrees",
      [](const Quality& q) { return q.min_angle_p5; }, false, 1);
  print_pivot(
      rows, first_weight, "Share of the new vertices with valence 6, %",
      [](const Quality& q) { return 100.0 * q.valence6_share; }, false, 0);
  print_pivot(
      rows, first_weight, "Largest dihedral angle across the hole's boundary, degrees",
      [](const Quality& q) { return q.max_boundary_dihedral; }, true, 1);
  std::cout << "**Every measure**\n\n";
  print_table(rows);
}

int run(int argc, char** argv) {
  const Arguments a = parse_arguments(argc, argv);
  if (a.help) {
    std::cout << kUsage;
    return 0;
  }
  const std::vector<Method> methods = methods_of(a);
  if (a.write_dir) std::filesystem::create_directories(*a.write_dir);
  std::vector<Row> rows;
  for (const auto& shape : shapes(a.assets)) {
    if (!a.mesh_names.empty() &&
        std::find(a.mesh_names.begin(), a.mesh_names.end(), shape.name) == a.mesh_names.end()) {
      continue;
    }
    const Mesh closed = shape.make();
    const Truth truth(closed);
    for (const auto& radii : a.cuts) {
      std::string problem;
      const auto cut = cut_holes(closed, radii, a.seed, &problem);
      if (!cut) {
        std::cerr << "holefill-quality: " << shape.name << ": " << problem << "\n";
        continue;
      }
      measure_cut(shape, closed, truth, *cut, a, methods, rows);
    }
  }
  print_results(rows, a.weight_names);
  return 0;
}

}  // namespace
}  // namespace holefill::quality

int main(int argc, char** argv) {
  return holefill::quality::run_guarded("holefill-quality", holefill::quality::kUsage,
                                        [&] { return holefill::quality::run(argc, argv); });
}
