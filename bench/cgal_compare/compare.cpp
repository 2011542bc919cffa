// Side by side with CGAL: the same wavy holes through CGAL's triangulate_hole_polyline (full
// search and Delaunay-restricted) and through ours, in one process; prints times, ratios and the
// patches' smallest angle and largest dihedral angle, so speed is never bought with worse patches.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bench_holes.h"
#include "cgal_triangulate.h"

namespace holefill::bench {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

// Best of `repeats` runs, in seconds: the least disturbed by the rest of the machine.
double best_time(int repeats, const std::function<void()>& work) {
  double best = INFINITY;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

// The far vertex of a face across edge (i, i+1) whose normal is the polygon's outside normal.
std::vector<std::array<double, 3>> third_points(const HolePolygon& polygon) {
  std::vector<std::array<double, 3>> thirds;
  const std::size_t n = polygon.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = polygon.points[i];
    const Point& b = polygon.points[(i + 1) % n];
    const Point& normal = polygon.outside_normals[i];
    // The outside face runs b -> a -> t; t lies away from the hole, in the face's plane.
    const Point away = OpenMesh::cross(b - a, normal).normalized() * (b - a).norm();
    const Point t = (a + b) * 0.5 + away;
    thirds.push_back({t[0], t[1], t[2]});
  }
  return thirds;
}

struct Row {
  double seconds;
  TriangulationQuality quality;
};

void print(const char* name, int n, const Row& row, double cgal_full, double cgal_delaunay) {
  std::printf("| %d | %s | %.4f | %.1fx | %.1fx | %.2f | %.2f |\n", n, name, row.seconds,
              cgal_full / row.seconds, cgal_delaunay / row.seconds,
              row.quality.min_angle * kDegrees, row.quality.max_dihedral * kDegrees);
}

}  // namespace
}  // namespace holefill::bench

int main(int argc, char** argv) {
  using namespace holefill;
  using namespace holefill::bench;
  std::vector<int> sizes{100, 200, 400, 500, 800};
  if (argc > 1) {
    sizes.clear();
    for (int a = 1; a < argc; ++a) sizes.push_back(std::atoi(argv[a]));
  }
  std::printf(
      "| edges | method | seconds | vs CGAL full | vs CGAL Delaunay | min angle | max dihedral "
      "|\n");
  std::printf("|---:|---|---:|---:|---:|---:|---:|\n");
  for (const int n : sizes) {
    const HolePolygon polygon = wavy_hole(n);
    std::vector<std::array<double, 3>> points;
    for (const auto& p : polygon.points) points.push_back({p[0], p[1], p[2]});
    const auto thirds = third_points(polygon);
    const int repeats = n <= 200 ? 5 : (n <= 500 ? 2 : 1);

    std::vector<std::array<int, 3>> full, delaunay;
    const double cgal_full =
        best_time(repeats, [&] { full = cgal_triangulate_polyline(points, thirds, false); });
    const double cgal_delaunay =
        best_time(repeats, [&] { delaunay = cgal_triangulate_polyline(points, thirds, true); });
    print("CGAL full", n, {cgal_full, evaluate_triangulation(polygon, full)}, cgal_full,
          cgal_delaunay);
    print("CGAL Delaunay", n, {cgal_delaunay, evaluate_triangulation(polygon, delaunay)}, cgal_full,
          cgal_delaunay);
    // Ours with the full search forced (whatever the size) on one thread and on every core
    // (named, not left to the search's own choice by the load average, which this program's
    // CGAL runs raise), and with the restricted search (what holes above
    // RestrictedSearch::above_edges get by default).
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const std::vector<std::pair<bool, unsigned>> searches{
        {false, 1u}, {false, cores}, {true, 0u}};  // (restricted, threads; 0: its own choice)
    for (const auto& [restricted, threads] : searches) {
      if (!restricted && threads == cores && cores == 1) continue;
      for (const auto weight : {WeightKind::Liepa, WeightKind::MaxMin}) {
        TriangulateOptions options{weight};
        options.restricted.above_edges = 0;
        options.threads = threads;
        std::optional<PolygonTriangulation> ours;
        const double seconds = best_time(repeats, [&] {
          ours = restricted ? triangulate_polygon_restricted(polygon, options)
                            : triangulate_polygon(polygon, options);
        });
        const std::string name = "holefill " + to_string(weight) +
                                 (restricted ? std::string(" restricted")
                                             : " full, " + std::to_string(threads) +
                                                   (threads == 1 ? " thread" : " threads"));
        print(name.c_str(), n, {seconds, ours->quality}, cgal_full, cgal_delaunay);
      }
    }
  }
}
