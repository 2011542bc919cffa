#include "test_meshes.h"

#include <cmath>
#include <cstring>
#include <map>
#include <numbers>

namespace holefill::testing {

void append_mesh(Mesh& mesh, const Mesh& part, const Point& offset) {
  std::vector<VertexHandle> added;
  for (const auto v : part.vertices()) added.push_back(mesh.add_vertex(part.point(v) + offset));
  for (const auto f : part.faces()) {
    std::vector<VertexHandle> corners;
    for (const auto v : part.fv_range(f)) corners.push_back(added[v.idx()]);
    mesh.add_face(corners);
  }
}

Mesh make_icosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Point> points{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                            {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                            {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> faces{
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& p : points) p.normalize();
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto found = midpoint.find(key);
      if (found != midpoint.end()) return found->second;
      points.push_back(((points[a] + points[b]) * 0.5).normalized());
      return midpoint[key] = static_cast<int>(points.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& f : faces) {
      const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  Mesh mesh;
  for (const auto& p : points) mesh.add_vertex(p);
  for (const auto& f : faces) {
    mesh.add_face(VertexHandle(f[0]), VertexHandle(f[1]), VertexHandle(f[2]));
  }
  return mesh;
}

Mesh make_grid(int n, const std::function<double(double, double)>& height) {
  Mesh mesh;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = static_cast<double>(i) / (n - 1), y = static_cast<double>(j) / (n - 1);
      mesh.add_vertex(Point(x, y, height(x, y)));
    }
  }
  auto at = [n](int i, int j) { return VertexHandle(j * n + i); };
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return mesh;
}

Mesh sphere_with_two_holes() {
  return without_faces(make_icosphere(3), [](const Point& c) {
    const double angle = std::atan2(c[1], c[0]);
    const bool cap = c[2] > 0.55 + 0.12 * std::sin(5.0 * angle);
    const bool small = (c - Point(0.0, 0.0, -1.0)).norm() < 0.25;
    return cap || small;
  });
}

Mesh without_faces(const Mesh& mesh, const std::function<bool(const Point&)>& remove) {
  return without_faces_where(mesh,
                             [&](const Point& centroid, const Point&) { return remove(centroid); });
}

Mesh without_faces_where(const Mesh& mesh,
                         const std::function<bool(const Point&, const Point&)>& remove) {
  Mesh cut;
  for (const auto v : mesh.vertices()) cut.add_vertex(mesh.point(v));
  for (const auto f : mesh.faces()) {
    std::vector<VertexHandle> corners;
    Point centroid(0, 0, 0);
    for (const auto v : mesh.fv_range(f)) {
      corners.push_back(v);
      centroid += mesh.point(v) / 3.0;
    }
    if (!remove(centroid, mesh.calc_face_normal(f))) cut.add_face(corners);
  }
  return cut;
}

Mesh grid_with_square_holes(int n) {
  const auto in_a_hole = [n](const Point& centroid) {
    const int x = static_cast<int>(centroid[0] * n), y = static_cast<int>(centroid[1] * n);
    return x % 3 == 1 && y % 3 == 1;
  };
  return without_faces(make_grid(n + 1, [](double, double) { return 0.0; }), in_a_hole);
}

std::vector<Point> random_loop(int n, std::mt19937& rng, double noise, double waviness) {
  std::uniform_real_distribution<double> jitter(-noise, noise);
  std::vector<Point> points;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / n + jitter(rng) * std::numbers::pi / n;
    const double radius = 1.0 + 0.5 * jitter(rng);
    points.emplace_back(radius * std::cos(angle), radius * std::sin(angle),
                        waviness * std::sin(3.0 * angle) + 0.3 * jitter(rng));
  }
  return points;
}

HolePolygon wavy_hole(int n, unsigned seed) {
  std::mt19937 rng(seed);
  HolePolygon polygon;
  polygon.points = random_loop(n, rng, 0.3, 0.35);
  for (int i = 0; i < n; ++i) {
    const Point mid = (polygon.points[i] + polygon.points[(i + 1) % n]) * 0.5;
    polygon.outside_normals.push_back(
        (Point(0, 0, 1) + 0.4 * Point(mid[0], mid[1], 0)).normalized());
  }
  return polygon;
}

bool original_part_unchanged(const Mesh& before, const Mesh& after) {
  if (after.n_vertices() < before.n_vertices() || after.n_faces() < before.n_faces()) {
    return false;
  }
  for (const auto v : before.vertices()) {
    const Point &a = before.point(v), &b = after.point(VertexHandle(v.idx()));
    if (std::memcmp(&a, &b, sizeof(Point)) != 0) return false;
  }
  for (const auto f : before.faces()) {
    std::vector<int> a, b;
    for (const auto v : before.fv_range(f)) a.push_back(v.idx());
    for (const auto v : after.fv_range(FaceHandle(f.idx()))) b.push_back(v.idx());
    if (a != b) return false;
  }
  return true;
}

bool is_oriented_manifold(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> directed_edges;
  for (const auto f : mesh.faces()) {
    std::vector<int> corners;
    for (const auto v : mesh.fv_range(f)) corners.push_back(v.idx());
    if (corners.size() != 3) return false;
    for (int c = 0; c < 3; ++c) {
      if (++directed_edges[{corners[c], corners[(c + 1) % 3]}] > 1) return false;
    }
  }
  for (const auto v : mesh.vertices()) {
    if (!mesh.is_manifold(v)) return false;
  }
  return true;
}

}  // namespace holefill::testing
