// holefill-features: do the fills continue sharp features? Cuts one hole out of each closed mesh
// of the CAD set (cad_cases.h: generated boxes, cylinders, fillets and steps, and real parts given
// with --real), across a crease, a corner, a rim or a fillet; fills it with our recipes and with
// CGAL's triangulate_refine_and_fair_hole (when built with CGAL); measures each fill against the
// surface that was cut away (crease_measure.h) and prints Markdown tables. See README.md.
//
//   holefill-features [--cases a,b] [--recipes a,b] [--feature-angle D] [--real FILE]...
//                     [--real-edge F] [--seed N] [--write DIR]
#include "holefill/features.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench_text.h"
#include "cad_cases.h"
#include "crease_measure.h"
#include "feature_tables.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/prepare.h"
#include "island_meshes.h"
#include "test_meshes.h"
#ifdef HOLEFILL_QUALITY_WITH_CGAL
#include "cgal_bridge.h"
#endif

namespace holefill::features {
namespace {

using quality::split;
using quality::UsageError;

constexpr const char* kUsage = R"(usage: holefill-features [options]

  --cases a,b       the cases to run (default: all; names as in the tables)
  --recipes a,b     default (holefill fill's defaults: sharp features continued),
                    default-nofeatures (--feature-angle 0: the paper's fill), fair3-remesh
                    (--smooth fair --fair-order 3 --remesh on), fair3-remesh-nofeatures,
                    cgal (CGAL's triangulate_refine_and_fair_hole), truth (the cut-away faces
                    themselves) (default: all that this build has)
  --feature-angle D the feature recipes' --feature-angle (default: the library's, 40)
  --real FILE       also a real closed mesh (repeatable): a hole across one of its creases and
                    one across a corner
  --real-edge F     real meshes' edges are split until none is longer than F times the
                    bounding-box diagonal (default 0.02)
  --seed N          seed for the real meshes' hole centres (default 1)
  --write DIR       also write every cut and filled mesh there as OBJ
)";

struct Arguments {
  std::vector<std::string> cases, recipes;
  std::vector<std::filesystem::path> real;
  double real_edge = 0.02;
  double feature_angle = FeatureOptions{}.angle_degrees;
  unsigned seed = 1;
  std::optional<std::filesystem::path> write_dir;
  bool help = false;
};

std::vector<std::string> all_recipes() {
  std::vector<std::string> recipes{"default", "default-nofeatures", "fair3-remesh",
                                   "fair3-remesh-nofeatures"};
#ifdef HOLEFILL_QUALITY_WITH_CGAL
  recipes.push_back("cgal");
#endif
  recipes.push_back("truth");
  return recipes;
}

Arguments parse_arguments(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError{arg + " needs a value"};
      return argv[++i];
    };
    if (arg == "--cases") {
      a.cases = split(value());
    } else if (arg == "--recipes") {
      a.recipes = split(value());
    } else if (arg == "--real") {
      a.real.emplace_back(value());
    } else if (arg == "--real-edge") {
      a.real_edge = std::stod(value());
    } else if (arg == "--feature-angle") {
      a.feature_angle = std::stod(value());
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
  const auto known = all_recipes();
  if (a.recipes.empty()) a.recipes = known;
  for (const auto& r : a.recipes) {
    if (std::find(known.begin(), known.end(), r) == known.end()) {
      std::string names;
      for (const auto& k : known) names += (names.empty() ? "" : ", ") + k;
      throw UsageError{"unknown recipe '" + r + "' (this build has: " + names + ")"};
    }
  }
  return a;
}

// A real mesh, closed and manifold after the loader's stitching, its long edges split and its
// flat parts' edges flipped to Delaunay.
Mesh load_real(const std::filesystem::path& path, double edge_fraction) {
  Mesh mesh = load_mesh(path);
  prepare_mesh(mesh);
  mesh.garbage_collection();
  if (!testing::is_oriented_manifold(mesh) || !find_holes(mesh).empty()) {
    throw std::runtime_error(path.string() + ": not a closed manifold mesh after stitching");
  }
  Point low = mesh.point(*mesh.vertices_begin()), high = low;
  for (const auto v : mesh.vertices()) {
    low.minimize(mesh.point(v));
    high.maximize(mesh.point(v));
  }
  split_long_edges(mesh, edge_fraction * (high - low).norm());
  flip_flat_edges_to_delaunay(mesh);
  return mesh;
}

// Our recipes: "-nofeatures" turns the feature continuation off (angle 0), else `feature_angle`.
FillOptions recipe_options(const std::string& recipe, double feature_angle) {
  FillOptions options;
  const std::string off = "-nofeatures";
  const bool features = !recipe.ends_with(off);
  options.features.angle_degrees = features ? feature_angle : 0.0;
  if (recipe.starts_with("fair3-remesh")) {
    options.smooth.method = SmoothMethod::Fair;
    options.smooth.fair.order = 3;
    options.refine.remesh = true;
  }
  return options;
}

// Fills the case's hole with one recipe and measures the fill.
Row fill_and_measure(const CadCase& c, const quality::CutMesh& cut, const quality::Truth& truth,
                     const std::string& recipe, const Arguments& a) {
  const auto loops = find_holes(cut.mesh);
  const quality::CutHole& hole = cut.holes.front();
  Row row{c.name, c.what, recipe, loops.front().size(), {}, ""};
  Mesh filled;
  quality::FilledHole patch;
  if (recipe == "truth") {
    patch = {loops.front().vertices, hole.removed_faces, hole.inner_vertices};
    row.quality = measure_feature_fill(c.closed, truth, hole, c.closed, patch, false);
    return row;
  }
  if (recipe == "cgal") {
#ifdef HOLEFILL_QUALITY_WITH_CGAL
    std::vector<quality::FilledHole> patches;
    std::size_t unfaired = 0;
    filled = quality::fill_with_cgal(cut.mesh, loops, patches, unfaired);
    patch = patches.front();
    if (unfaired) row.notes = "not faired";
#endif
  } else {
    filled = cut.mesh;
    const auto fills = fill_holes(filled, loops, recipe_options(recipe, a.feature_angle));
    const HoleFill& fill = fills.front();
    patch = {fill.patch.boundary, fill.patch.faces, fill.patch.new_vertices};
    if (fill.failed()) row.notes = "not filled: " + fill.failure.message;
    if (!fill.smoothing_note.empty()) row.notes += fill.smoothing_note + " ";
    if (!fill.creases.empty()) row.notes += std::to_string(fill.creases.size()) + " creases ";
    if (!fill.features_note.empty()) row.notes += fill.features_note;
  }
  row.quality = measure_feature_fill(c.closed, truth, hole, filled, patch, true);
  if (a.write_dir) save_mesh(filled, *a.write_dir / (c.name + "-" + recipe + ".obj"));
  return row;
}

int run(int argc, char** argv) {
  const Arguments a = parse_arguments(argc, argv);
  if (a.help) {
    std::cout << kUsage;
    return 0;
  }
  if (a.write_dir) std::filesystem::create_directories(*a.write_dir);
  std::vector<CadCase> cases = generated_cases();
  for (const auto& path : a.real) {
    const auto more =
        real_cases(path.stem().string(), load_real(path, a.real_edge), kSharpDegrees, 4.0, a.seed);
    if (more.empty()) std::cerr << "holefill-features: " << path.string() << ": no case placed\n";
    cases.insert(cases.end(), more.begin(), more.end());
  }
  std::vector<Row> rows;
  for (const auto& c : cases) {
    if (!a.cases.empty() && std::find(a.cases.begin(), a.cases.end(), c.name) == a.cases.end()) {
      continue;
    }
    std::string problem;
    const auto cut = cut_case(c, &problem);
    if (!cut) {
      std::cerr << "holefill-features: " << c.name << ": " << problem << "\n";
      continue;
    }
    if (a.write_dir) {
      // Without the hole's unused vertices: the file opens as a mesh with one hole, nothing else.
      save_mesh(testing::without_isolated_vertices(cut->mesh),
                *a.write_dir / (c.name + "-cut.obj"));
    }
    const quality::Truth truth(c.closed);
    for (const auto& recipe : a.recipes)
      rows.push_back(fill_and_measure(c, *cut, truth, recipe, a));
  }
  print_tables(rows, a.recipes);
  return 0;
}

}  // namespace
}  // namespace holefill::features

int main(int argc, char** argv) {
  return holefill::quality::run_guarded("holefill-features", holefill::features::kUsage,
                                        [&] { return holefill::features::run(argc, argv); });
}
