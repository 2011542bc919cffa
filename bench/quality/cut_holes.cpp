#include "cut_holes.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <random>

#include "holefill/holes.h"

namespace holefill::quality {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kSeedAttempts = 400;

// Shortest distances along edges from `source`, up to `limit` (farther vertices stay infinite).
std::vector<double> edge_distances(const Mesh& mesh, VertexHandle source, double limit) {
  std::vector<double> distance(mesh.n_vertices(), kInfinity);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  distance[source.idx()] = 0.0;
  queue.emplace(0.0, source.idx());
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v] || d > limit) continue;
    for (const auto h : mesh.voh_range(VertexHandle(v))) {
      const int w = mesh.to_vertex_handle(h).idx();
      const double through = d + mesh.calc_edge_length(h);
      if (through < distance[w]) {
        distance[w] = through;
        queue.emplace(through, w);
      }
    }
  }
  return distance;
}

// Grows `removed` until the kept faces' border is a simple loop: no kept face with two or more
// edges on the hole, no vertex whose kept faces form two fans.
void clean_up(const Mesh& mesh, std::vector<char>& removed) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto f : mesh.faces()) {
      if (removed[f.idx()]) continue;
      int hole_edges = 0;
      for (const auto g : mesh.ff_range(f)) hole_edges += removed[g.idx()];
      if (hole_edges >= 2) removed[f.idx()] = changed = true;
    }
    for (const auto v : mesh.vertices()) {
      std::vector<char> fan;
      for (const auto f : mesh.vf_range(v)) fan.push_back(removed[f.idx()]);
      int runs = 0;
      for (std::size_t i = 0; i < fan.size(); ++i) {
        runs += fan[i] && !fan[(i + fan.size() - 1) % fan.size()];
      }
      if (runs > 1) {
        for (const auto f : mesh.vf_range(v)) removed[f.idx()] = 1;
        changed = true;
      }
    }
  }
}

// The edge-connected piece of the faces for which `inside` holds that contains `start`, cleaned
// up into a disk.
std::vector<char> grow_disk(const Mesh& mesh, const std::vector<FaceHandle>& start,
                            const std::function<bool(FaceHandle)>& inside) {
  std::vector<char> removed(mesh.n_faces(), 0);
  std::vector<FaceHandle> stack;
  for (const auto f : start) {
    removed[f.idx()] = 1;
    stack.push_back(f);
  }
  while (!stack.empty()) {
    const FaceHandle f = stack.back();
    stack.pop_back();
    for (const auto g : mesh.ff_range(f)) {
      if (!removed[g.idx()] && inside(g)) {
        removed[g.idx()] = 1;
        stack.push_back(g);
      }
    }
  }
  clean_up(mesh, removed);
  return removed;
}

// The removed faces around one seed: centroids within `radius` along edges.
std::vector<char> disk_around(const Mesh& mesh, VertexHandle seed, double radius) {
  const std::vector<double> distance = edge_distances(mesh, seed, 2.0 * radius);
  std::vector<FaceHandle> start;
  for (const auto f : mesh.vf_range(seed)) start.push_back(f);
  return grow_disk(mesh, start, [&](FaceHandle f) {
    double sum = 0.0;
    for (const auto v : mesh.fv_range(f)) sum += distance[v.idx()];
    return sum / 3.0 < radius;
  });
}

long euler_characteristic(const Mesh& mesh) {
  long used = 0;
  for (const auto v : mesh.vertices()) used += mesh.is_isolated(v) ? 0 : 1;
  return used - static_cast<long>(mesh.n_edges()) + static_cast<long>(mesh.n_faces());
}

// The closed mesh without the removed faces, or nothing when OpenMesh refuses a face (the
// kept faces would not be manifold).
std::optional<Mesh> without(const Mesh& closed, const std::vector<char>& removed) {
  Mesh cut;
  for (const auto v : closed.vertices()) cut.add_vertex(closed.point(v));
  for (const auto f : closed.faces()) {
    if (removed[f.idx()]) continue;
    std::vector<VertexHandle> corners;
    for (const auto v : closed.fv_range(f)) corners.push_back(v);
    if (!cut.add_face(corners).is_valid()) return std::nullopt;
  }
  return cut;
}

CutHole hole_of(const Mesh& closed, const std::vector<char>& disk, VertexHandle seed,
                double radius) {
  CutHole hole;
  hole.seed = seed;
  hole.radius = radius;
  for (const auto f : closed.faces()) {
    if (disk[f.idx()]) hole.removed_faces.push_back(f);
  }
  for (const auto v : closed.vertices()) {
    bool all_removed = true;
    for (const auto f : closed.vf_range(v)) all_removed = all_removed && disk[f.idx()];
    if (all_removed) hole.inner_vertices.push_back(v);
  }
  return hole;
}

}  // namespace

double mean_edge_length(const Mesh& mesh) {
  double total = 0.0;
  for (const auto e : mesh.edges()) total += mesh.calc_edge_length(e);
  return mesh.n_edges() ? total / static_cast<double>(mesh.n_edges()) : 0.0;
}

std::optional<CutMesh> cut_holes(const Mesh& closed, const std::vector<double>& radii,
                                 unsigned seed, std::string* problem) {
  const double edge = mean_edge_length(closed);
  const long closed_euler = euler_characteristic(closed);
  std::mt19937 rng(seed);
  std::vector<char> removed(closed.n_faces(), 0);
  std::vector<char> near_a_hole(closed.n_vertices(), 0);
  CutMesh result;
  for (std::size_t k = 0; k < radii.size(); ++k) {
    const double radius = radii[k] * edge;
    bool placed = false;
    for (int attempt = 0; attempt < kSeedAttempts && !placed; ++attempt) {
      // rng() itself is specified exactly by the standard; the distributions are not.
      const VertexHandle candidate(static_cast<int>(rng() % closed.n_vertices()));
      if (near_a_hole[candidate.idx()]) continue;
      const std::vector<char> disk = disk_around(closed, candidate, radius);
      bool overlaps = false;
      std::vector<char> together = removed;
      for (const auto f : closed.faces()) {
        if (!disk[f.idx()]) continue;
        for (const auto v : closed.fv_range(f)) overlaps = overlaps || near_a_hole[v.idx()];
        together[f.idx()] = 1;
      }
      if (overlaps) continue;
      const auto cut = without(closed, together);
      if (!cut) continue;
      const auto loops = find_holes(*cut);
      const bool clean =
          loops.size() == k + 1 &&
          std::none_of(loops.begin(), loops.end(), [](const Hole& h) { return h.pinched; }) &&
          euler_characteristic(*cut) == closed_euler - static_cast<long>(k + 1);
      if (!clean) continue;

      CutHole hole = hole_of(closed, disk, candidate, radius);
      // Later holes keep two edge lengths of surface between themselves and this one.
      for (const auto f : hole.removed_faces) {
        for (const auto v : closed.fv_range(f)) {
          const auto distance = edge_distances(closed, v, 2.0 * edge);
          for (std::size_t i = 0; i < distance.size(); ++i) {
            if (distance[i] <= 2.0 * edge) near_a_hole[i] = 1;
          }
        }
      }
      removed = std::move(together);
      result.mesh = std::move(*cut);
      result.holes.push_back(std::move(hole));
      placed = true;
    }
    if (!placed) {
      if (problem) {
        *problem = "could not place a clean hole of radius " + std::to_string(radii[k]) +
                   " edge lengths after " + std::to_string(kSeedAttempts) + " seeds";
      }
      return std::nullopt;
    }
  }
  if (radii.empty()) result.mesh = closed;
  return result;
}

std::optional<CutMesh> cut_ball(const Mesh& closed, const Point& center, double radius,
                                std::string* problem) {
  auto centroid = [&](FaceHandle f) {
    Point sum(0.0, 0.0, 0.0);
    for (const auto v : closed.fv_range(f)) sum += closed.point(v);
    return sum / 3.0;
  };
  FaceHandle nearest;
  double nearest_distance = kInfinity;
  for (const auto f : closed.faces()) {
    const double d = (centroid(f) - center).norm();
    if (d < nearest_distance) nearest_distance = d, nearest = f;
  }
  auto fail = [&](const std::string& why) -> std::optional<CutMesh> {
    if (problem) *problem = why;
    return std::nullopt;
  };
  if (!nearest.is_valid()) return fail("the mesh has no faces");
  const std::vector<char> disk = grow_disk(
      closed, {nearest}, [&](FaceHandle f) { return (centroid(f) - center).norm() < radius; });
  auto cut = without(closed, disk);
  if (!cut) return fail("the faces left would not be manifold");
  const auto loops = find_holes(*cut);
  if (loops.size() != 1 || loops[0].pinched ||
      euler_characteristic(*cut) != euler_characteristic(closed) - 1) {
    return fail("the cut is not one disk bounded by one simple loop (" +
                std::to_string(loops.size()) + " loops)");
  }
  CutMesh result;
  result.mesh = std::move(*cut);
  result.holes.push_back(
      hole_of(closed, disk, closed.from_vertex_handle(closed.halfedge_handle(nearest)), radius));
  return result;
}

}  // namespace holefill::quality
