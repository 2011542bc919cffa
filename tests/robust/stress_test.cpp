// Stress: five hundred random meshes (spheres, terrains, tori and tubes with random
// faces and balls of faces removed, jittered points, flipped and duplicated faces, small bodies
// dropped near the holes), filled with random parameters, all at once or stepped hole by hole in
// a random order like the viewer does; every fill must keep the guarantees.
#include <map>
#include <numbers>

#include "fill_guarantees.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "robust_test_util.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

using Rng = std::mt19937;

double uniform(Rng& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}
int integer(Rng& rng, int low, int high) {
  return std::uniform_int_distribution<int>(low, high)(rng);
}
bool chance(Rng& rng, double p) { return std::bernoulli_distribution(p)(rng); }

Soup torus(int around, int across, double r) {
  Soup soup;
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      const double u = 2 * std::numbers::pi * i / around, v = 2 * std::numbers::pi * j / across;
      soup.points.emplace_back((1 + r * std::cos(v)) * std::cos(u),
                               (1 + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  }
  auto at = [&](int i, int j) { return (i % around) * across + (j % across); };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      soup.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      soup.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return soup;
}

Soup tube(int around, int rings) {
  Soup soup;
  for (int k = 0; k <= rings; ++k) {
    for (int i = 0; i < around; ++i) {
      const double u = 2 * std::numbers::pi * i / around;
      soup.points.emplace_back(std::cos(u), std::sin(u), 2.0 * k / rings);
    }
  }
  for (int k = 0; k < rings; ++k) {
    for (int i = 0; i < around; ++i) {
      const int a = k * around + i, b = k * around + (i + 1) % around;
      soup.faces.push_back({a, b, b + around});
      soup.faces.push_back({a, b + around, a + around});
    }
  }
  return soup;
}

Soup random_shape(Rng& rng, std::string& name) {
  switch (integer(rng, 0, 3)) {
    case 0: {
      const int levels = integer(rng, 1, 3);
      name = "icosphere " + std::to_string(levels);
      return soup_of(make_icosphere(levels));
    }
    case 1: {
      const int n = integer(rng, 5, 20);
      const double a = uniform(rng, 0, 0.4), fx = uniform(rng, 1, 8), fy = uniform(rng, 1, 8);
      name = "terrain " + std::to_string(n);
      return soup_of(make_grid(
          n, [=](double x, double y) { return a * std::sin(fx * x) * std::cos(fy * y); }));
    }
    case 2: {
      const int around = integer(rng, 8, 30), across = integer(rng, 5, 14);
      name = "torus " + std::to_string(around) + "x" + std::to_string(across);
      return torus(around, across, uniform(rng, 0.2, 0.6));
    }
    default: {
      const int around = integer(rng, 6, 40), rings = integer(rng, 1, 8);
      name = "tube " + std::to_string(around) + "x" + std::to_string(rings);
      return tube(around, rings);
    }
  }
}

// Holes: random single faces and balls of faces; then jitter, flips, duplicates.
Soup damage(Soup soup, Rng& rng) {
  const double single = chance(rng, 0.5) ? uniform(rng, 0.0, 0.08) : 0.0;
  std::vector<std::pair<Point, double>> balls;
  for (int b = integer(rng, 0, 4); b > 0; --b) {
    const auto& corner = soup.points[integer(rng, 0, static_cast<int>(soup.points.size()) - 1)];
    balls.emplace_back(corner, uniform(rng, 0.05, 0.6));
  }
  std::erase_if(soup.faces, [&](const std::vector<int>& f) {
    Point c(0, 0, 0);
    for (const int v : f) c += soup.points[v] / 3.0;
    for (const auto& [centre, radius] : balls) {
      if ((c - centre).norm() < radius) return true;
    }
    return chance(rng, single);
  });
  if (chance(rng, 0.5)) {
    const double amount = uniform(rng, 0.0, 0.02);
    for (auto& p : soup.points)
      p += Point(uniform(rng, -amount, amount), uniform(rng, -amount, amount),
                 uniform(rng, -amount, amount));
  }
  if (chance(rng, 0.2)) {
    for (auto& f : soup.faces) {
      if (chance(rng, 0.05)) std::swap(f[1], f[2]);
    }
  }
  if (chance(rng, 0.1) && !soup.faces.empty()) {
    soup.faces.push_back(soup.faces[integer(rng, 0, static_cast<int>(soup.faces.size()) - 1)]);
  }
  return soup;
}

// A small tetrahedron near a random hole, sometimes right across it.
void drop_body(Mesh& mesh, const std::vector<Hole>& holes, Rng& rng) {
  if (holes.empty()) return;
  const Hole& hole = holes[integer(rng, 0, static_cast<int>(holes.size()) - 1)];
  const double size = std::max(1e-3, hole.mean_surrounding_edge_length) * uniform(rng, 0.3, 3.0);
  const Point centre =
      hole.centroid + Point(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) * size;
  VertexHandle v[4];
  v[0] = mesh.add_vertex(centre + Point(size, 0, -size / 3));
  v[1] = mesh.add_vertex(centre + Point(-size / 2, size * 0.87, -size / 3));
  v[2] = mesh.add_vertex(centre + Point(-size / 2, -size * 0.87, -size / 3));
  v[3] = mesh.add_vertex(centre + Point(0, 0, size));
  mesh.add_face(v[0], v[1], v[2]);
  mesh.add_face(v[0], v[3], v[1]);
  mesh.add_face(v[1], v[3], v[2]);
  mesh.add_face(v[2], v[3], v[0]);
}

FillOptions random_options(Rng& rng) {
  FillOptions options;
  options.triangulate.weight =
      std::array{WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}[integer(rng, 0, 2)];
  options.triangulate.fold_limit = uniform(rng, 0.5, std::numbers::pi);
  options.refine.tau = uniform(rng, 0.7, 2.2);
  options.smooth.method = chance(rng, 0.3) ? SmoothMethod::Fair : SmoothMethod::Umbrella;
  options.smooth.iterations = integer(rng, 0, 25);
  options.smooth.step = uniform(rng, 0.05, 1.0);
  options.smooth.fair.order = integer(rng, 2, 3);
  options.smooth.fair.cotangent_weights = chance(rng, 0.7);
  options.last_stage = chance(rng, 0.8) ? Stage::Smoothed : static_cast<Stage>(integer(rng, 1, 2));
  options.refine.remesh = chance(rng, 0.3);
  return options;
}

// Steps the holes one stage at a time in a random order, as a viewer user might; checks the
// guarantees halfway too (a hole stopped after any stage holds a complete patch).
std::vector<HoleFill> step_randomly(Mesh& mesh, const Mesh& before, const std::vector<Hole>& holes,
                                    const FillOptions& options, Rng& rng, std::string& problem) {
  std::vector<HoleFill> fills(holes.size());
  std::vector<int> open(holes.size());
  std::iota(open.begin(), open.end(), 0);
  const std::size_t check_at = integer(rng, 0, static_cast<int>(3 * holes.size()));
  for (std::size_t step = 0; !open.empty(); ++step) {
    const int pick = integer(rng, 0, static_cast<int>(open.size()) - 1);
    const int id = open[pick];
    if (advance(mesh, holes[id], fills[id], options) != StageRun::Ran ||
        fills[id].stage() >= options.last_stage) {
      open.erase(open.begin() + pick);
    }
    if (step == check_at && problem.empty()) {
      problem = check_fill_guarantees(before, holes, mesh, fills);
      if (!problem.empty()) problem = "halfway: " + problem;
    }
  }
  return fills;
}

TEST(Stress, RandomMeshesAndParametersKeepEveryGuarantee) {
  constexpr int kMeshes = 500;
  std::map<std::string, int> outcomes;
  std::size_t holes_total = 0;
  for (int trial = 0; trial < kMeshes; ++trial) {
    Rng rng(1000 + trial);
    std::string shape;
    const Soup soup = damage(random_shape(rng, shape), rng);
    LoadReport report;
    Mesh before;
    try {
      before = load_mesh_from_memory(obj_text(soup), "stress.obj", &report);
    } catch (const InvalidMeshError&) {
      ++outcomes["no faces left"];
      continue;
    }
    auto holes = find_holes(before);
    if (chance(rng, 0.25)) {
      drop_body(before, holes, rng);
      holes = find_holes(before);
    }
    const FillOptions options = random_options(rng);
    Mesh after = before;
    std::string problem;
    const bool stepped = chance(rng, 0.3);
    const std::vector<HoleFill> fills =
        stepped ? step_randomly(after, before, holes, options, rng, problem)
                : fill_holes(after, holes, options);
    if (problem.empty()) problem = check_fill_guarantees(before, holes, after, fills);
    ASSERT_EQ(problem, "") << "trial " << trial << " (" << shape << ", " << holes.size()
                           << " holes, " << (stepped ? "stepped" : "all at once") << ")";
    // The grid fill_holes looks up nearby faces in finds what a scan of the whole mesh finds:
    // each count covers the mesh as it was when its hole was filled, so later patches can only
    // add to a count taken now.
    for (const auto& fill : fills) {
      if (fill.failed() || fill.stage() == Stage::Original) continue;
      ASSERT_LE(fill.self_intersections, count_patch_intersections(after, fill.patch))
          << "trial " << trial << " hole " << fill.hole_id;
    }
    if (!stepped && !fills.empty() && !fills.back().failed()) {
      ASSERT_EQ(fills.back().self_intersections,
                count_patch_intersections(after, fills.back().patch))
          << "trial " << trial;
    }
    holes_total += holes.size();
    for (const auto& fill : fills) {
      if (fill.failed()) {
        ++outcomes["failed: " + std::string(to_string(fill.failure.kind))];
      } else {
        ++outcomes["filled"];
      }
      if (fill.self_intersections) ++outcomes["filled, intersecting"];
      if (!fill.refinement_note.empty()) ++outcomes[fill.refinement_note];
      if (fill.refinement.remeshing.flips) ++outcomes["remeshed (some edge flipped)"];
      if (fill.smoothing_note.find("undone") != std::string::npos) ++outcomes["smoothing undone"];
    }
  }
  std::cout << holes_total << " holes in " << kMeshes << " meshes:\n";
  for (const auto& [what, count] : outcomes) std::cout << "  " << count << "  " << what << "\n";
  EXPECT_GT(outcomes["filled"], 1000);
}

}  // namespace
}  // namespace holefill::testing
