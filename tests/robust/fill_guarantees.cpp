#include "fill_guarantees.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "geometry.h"
#include "holefill/triangulate.h"

namespace holefill::testing {
namespace {

std::vector<int> corners_of(const Mesh& mesh, FaceHandle f) {
  std::vector<int> corners;
  for (const auto v : mesh.fv_range(f)) corners.push_back(v.idx());
  return corners;
}

std::vector<int> sorted_loop(const Hole& hole) {
  std::vector<int> halfedges;
  for (const auto h : hole.halfedges) halfedges.push_back(h.idx());
  std::sort(halfedges.begin(), halfedges.end());
  return halfedges;
}

}  // namespace

std::string check_oriented(const Mesh& mesh) {
  std::set<std::pair<int, int>> directed;
  for (const auto f : mesh.faces()) {
    const auto c = corners_of(mesh, f);
    if (c.size() != 3) return "face " + std::to_string(f.idx()) + " is not a triangle";
    for (int i = 0; i < 3; ++i) {
      if (c[i] < 0 || c[i] >= static_cast<int>(mesh.n_vertices())) {
        return "face " + std::to_string(f.idx()) + " has an invalid corner";
      }
      if (c[i] == c[(i + 1) % 3]) return "face " + std::to_string(f.idx()) + " repeats a corner";
      if (!directed.emplace(c[i], c[(i + 1) % 3]).second) {
        return "edge " + std::to_string(c[i]) + "->" + std::to_string(c[(i + 1) % 3]) +
               " is used twice in one direction (face " + std::to_string(f.idx()) + ")";
      }
    }
  }
  return {};
}

std::string check_fill_guarantees(const Mesh& before, const std::vector<Hole>& holes,
                                  const Mesh& after, const std::vector<HoleFill>& fills) {
  // Only patch elements are added, and the original ones are untouched.
  if (after.n_vertices() < before.n_vertices() || after.n_faces() < before.n_faces()) {
    return "elements were removed";
  }
  for (const auto v : before.vertices()) {
    const Point &a = before.point(v), &b = after.point(VertexHandle(v.idx()));
    if (std::memcmp(&a, &b, sizeof(Point)) != 0) {
      return "original vertex " + std::to_string(v.idx()) + " moved";
    }
  }
  for (const auto f : before.faces()) {
    if (corners_of(before, f) != corners_of(after, FaceHandle(f.idx()))) {
      return "original face " + std::to_string(f.idx()) + " changed";
    }
  }
  std::set<int> patch_faces, patch_vertices;
  std::set<int> filled;
  for (const auto& fill : fills) {
    if (fill.failed()) {
      if (!fill.patch.faces.empty() || !fill.patch.new_vertices.empty()) {
        return "failed hole " + std::to_string(fill.hole_id) + " kept patch elements";
      }
      continue;
    }
    if (fill.stage() == Stage::Original) continue;
    filled.insert(fill.hole_id);
    filled.insert(fill.joined_holes.begin(), fill.joined_holes.end());  // its islands
    for (const auto f : fill.patch.faces) {
      if (!patch_faces.insert(f.idx()).second) return "a face is in two patches";
    }
    for (const auto v : fill.patch.new_vertices) {
      if (!patch_vertices.insert(v.idx()).second) return "a vertex is in two patches";
    }
  }
  for (int f = static_cast<int>(before.n_faces()); f < static_cast<int>(after.n_faces()); ++f) {
    if (!patch_faces.count(f)) return "face " + std::to_string(f) + " belongs to no patch";
  }
  for (int v = static_cast<int>(before.n_vertices()); v < static_cast<int>(after.n_vertices());
       ++v) {
    if (!patch_vertices.count(v)) return "vertex " + std::to_string(v) + " belongs to no patch";
  }
  if (patch_faces.size() != after.n_faces() - before.n_faces() ||
      patch_vertices.size() != after.n_vertices() - before.n_vertices()) {
    return "the patches list elements that are not new";
  }
  for (const auto v : after.vertices()) {
    if (v.idx() >= static_cast<int>(before.n_vertices())) {
      const Point& p = after.point(v);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
        return "patch vertex " + std::to_string(v.idx()) + " is not finite";
      }
    }
  }
  if (after.has_vertex_status()) {
    for (const auto v : after.all_vertices()) {
      if (after.status(v).deleted()) return "a deleted vertex is left in the mesh";
    }
    for (const auto f : after.all_faces()) {
      if (after.status(f).deleted()) return "a deleted face is left in the mesh";
    }
  }

  // Oriented, and no vertex that was manifold is made non-manifold.
  if (auto problem = check_oriented(after); !problem.empty()) return problem;
  for (const auto v : after.vertices()) {
    const bool was_manifold = v.idx() >= static_cast<int>(before.n_vertices()) ||
                              before.is_manifold(VertexHandle(v.idx()));
    if (was_manifold && !after.is_manifold(v)) {
      return "vertex " + std::to_string(v.idx()) + " became non-manifold";
    }
  }

  // No degenerate patch triangle.
  for (const int f : patch_faces) {
    std::vector<Point> p;
    for (const auto v : after.fv_range(FaceHandle(f))) p.push_back(after.point(v));
    if (geometry::measure_triangle(p[0], p[1], p[2], false).degenerate) {
      return "patch face " + std::to_string(f) + " is degenerate";
    }
  }

  // Each filled hole's loop is gone; every other loop is exactly as it was; no loop is new.
  const auto loops_after = find_holes(after);
  std::set<std::vector<int>> after_loops;
  for (const auto& hole : loops_after) after_loops.insert(sorted_loop(hole));
  for (const auto& hole : holes) {
    const bool is_filled = filled.count(hole.id) > 0;
    for (const auto h : hole.halfedges) {
      if (after.is_boundary(h) == is_filled) {
        return "hole " + std::to_string(hole.id) +
               (is_filled ? " was filled but part of its loop is still open"
                          : " was not filled but its loop changed");
      }
    }
    if (!is_filled && !after_loops.count(sorted_loop(hole))) {
      return "hole " + std::to_string(hole.id) + " is no longer the same loop";
    }
  }
  if (loops_after.size() != holes.size() - filled.size()) {
    return std::to_string(loops_after.size()) + " loops after filling " +
           std::to_string(filled.size()) + " of " + std::to_string(holes.size());
  }
  return {};
}

}  // namespace holefill::testing
