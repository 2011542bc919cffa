#include "dirty_meshes.h"

#include <cmath>
#include <map>

#include "test_meshes.h"

namespace holefill::testing {

Soup sphere_soup(int levels) { return soup_of(make_icosphere(levels)); }

Soup terrain_soup(int n) {
  return soup_of(
      make_grid(n, [](double x, double y) { return 0.15 * std::sin(5 * x) * std::cos(4 * y); }));
}

Soup dome_soup(int levels, double bottom) {
  return without(sphere_soup(levels), [bottom](const Point& c) { return c[2] < bottom; });
}

Point face_centroid(const Soup& soup, const std::vector<int>& face) {
  Point c(0, 0, 0);
  for (const int v : face) c += soup.points[v] / static_cast<double>(face.size());
  return c;
}

Soup without(Soup soup, const std::function<bool(const Point&)>& remove) {
  std::erase_if(soup.faces,
                [&](const std::vector<int>& f) { return remove(face_centroid(soup, f)); });
  return soup;
}

Soup with_hole(Soup soup, const Point& centre, double radius) {
  return without(std::move(soup), [&](const Point& c) { return (c - centre).norm() < radius; });
}

Soup append(Soup a, const Soup& b) {
  const int offset = static_cast<int>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (auto f : b.faces) {
    for (auto& c : f) c += offset;
    a.faces.push_back(f);
  }
  return a;
}

std::size_t cut_apart(Soup& soup, const std::function<bool(const Point&)>& side, double gap,
                      std::mt19937& rng, const std::function<bool(const Point&)>& on_cut) {
  std::vector<char> on_side(soup.faces.size()), used_off_side(soup.points.size(), 0);
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    on_side[f] = side(face_centroid(soup, soup.faces[f]));
    if (!on_side[f]) {
      for (const int c : soup.faces[f]) used_off_side[c] = 1;
    }
  }
  std::normal_distribution<double> normal;
  std::map<int, int> copy;
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    if (!on_side[f]) continue;
    for (int& c : soup.faces[f]) {
      if (!used_off_side[c] || (on_cut && !on_cut(soup.points[c]))) continue;
      if (!copy.count(c)) {
        Point offset(normal(rng), normal(rng), normal(rng));
        copy[c] = static_cast<int>(soup.points.size());
        soup.points.push_back(soup.points[c] +
                              (gap > 0 ? offset.normalized() * gap : Point(0, 0, 0)));
      }
      c = copy[c];
    }
  }
  return copy.size();
}

Soup box_of_separate_faces(int n) { return box_of_separate_faces({n, n, n, n, n, n}); }

Soup box_of_separate_faces(const std::array<int, 6>& points_per_side) {
  Soup box;
  // Each face: an origin corner and two axes, ordered so that the normal points outwards.
  const std::array<std::array<Point, 3>, 6> faces{{
      {Point(0, 0, 0), Point(0, 1, 0), Point(1, 0, 0)},  // z = 0
      {Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0)},  // z = 1
      {Point(0, 0, 0), Point(1, 0, 0), Point(0, 0, 1)},  // y = 0
      {Point(0, 1, 0), Point(0, 0, 1), Point(1, 0, 0)},  // y = 1
      {Point(0, 0, 0), Point(0, 0, 1), Point(0, 1, 0)},  // x = 0
      {Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)},  // x = 1
  }};
  for (std::size_t side = 0; side < faces.size(); ++side) {
    const auto& [origin, u, v] = faces[side];
    const int n = points_per_side[side];
    Soup grid;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        grid.points.push_back(origin + u * (static_cast<double>(i) / (n - 1)) +
                              v * (static_cast<double>(j) / (n - 1)));
      }
    }
    for (int j = 0; j + 1 < n; ++j) {
      for (int i = 0; i + 1 < n; ++i) {
        const int a = j * n + i;
        grid.faces.push_back({a, a + 1, a + n + 1});
        grid.faces.push_back({a, a + n + 1, a + n});
      }
    }
    box = append(std::move(box), grid);
  }
  return box;
}

}  // namespace holefill::testing
