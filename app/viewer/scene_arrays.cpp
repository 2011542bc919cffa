#include "scene_arrays.h"

#include <cmath>
#include <limits>

#include "holefill/attributes.h"

namespace holefill::viewer {
namespace {

glm::vec3 to_glm(const Point& p) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

}  // namespace

SurfaceArrays surface_arrays(const Mesh& mesh, const std::vector<const HoleFill*>& fills) {
  SurfaceArrays arrays;
  const std::size_t n_vertices = mesh.n_vertices();
  arrays.positions.reserve(n_vertices);
  arrays.lo = glm::vec3(std::numeric_limits<float>::max());
  arrays.hi = glm::vec3(std::numeric_limits<float>::lowest());
  for (const auto v : mesh.vertices()) {
    arrays.positions.push_back(to_glm(mesh.point(v)));
    arrays.lo = glm::min(arrays.lo, arrays.positions.back());
    arrays.hi = glm::max(arrays.hi, arrays.positions.back());
  }
  if (n_vertices == 0) arrays.lo = arrays.hi = glm::vec3(0.0f);
  std::vector<std::array<float, 3>> rgb;
  if (vertex_colors(mesh, rgb)) {
    arrays.colors.reserve(rgb.size());
    for (const auto& c : rgb) arrays.colors.emplace_back(c[0], c[1], c[2], 1.0f);
  }

  arrays.normals.assign(n_vertices, glm::vec3(0.0f));
  arrays.triangles.reserve(3 * mesh.n_faces());
  for (const auto f : mesh.faces()) {
    std::uint32_t corner[3];
    int i = 0;
    for (const auto v : mesh.fv_range(f)) {
      if (i < 3) corner[i] = static_cast<std::uint32_t>(v.idx());
      ++i;
    }
    const glm::vec3& a = arrays.positions[corner[0]];
    const glm::vec3& b = arrays.positions[corner[1]];
    const glm::vec3& c = arrays.positions[corner[2]];
    const glm::vec3 area_normal = glm::cross(b - a, c - a);  // length: twice the area
    for (const auto index : corner) {
      arrays.triangles.push_back(index);
      arrays.normals[index] += area_normal;
    }
  }
  for (auto& normal : arrays.normals) {
    const float length = glm::length(normal);
    normal = length > 0.0f ? normal / length : glm::vec3(0.0f, 0.0f, 1.0f);
  }

  arrays.face_stages.assign(mesh.n_faces(), static_cast<std::uint8_t>(Stage::Original));
  double edge_lengths = 0.0;
  std::size_t edges = 0;
  for (const HoleFill* fill : fills) {
    // Smoothing moves vertices and makes no faces: a smoothed patch is coloured as a whole.
    for (const auto f : fill->patch.faces) {
      const Stage stage = fill->stage() == Stage::Smoothed ? Stage::Smoothed : face_stage(mesh, f);
      arrays.face_stages[f.idx()] = static_cast<std::uint8_t>(stage);
    }
    for (const auto v : fill->patch.new_vertices) {
      arrays.patch_vertices.push_back(static_cast<std::uint32_t>(v.idx()));
      for (const auto w : mesh.vv_range(v)) {
        edge_lengths += glm::length(arrays.positions[w.idx()] - arrays.positions[v.idx()]);
        ++edges;
      }
    }
  }
  if (edges > 0) arrays.patch_edge_length = static_cast<float>(edge_lengths / edges);

  arrays.edges.reserve(2 * mesh.n_edges());
  arrays.vertex_edge_lengths.assign(n_vertices, 0.0f);
  std::vector<std::uint32_t> valence(n_vertices, 0);
  for (const auto e : mesh.edges()) {
    const auto h = mesh.halfedge_handle(e, 0);
    const auto a = static_cast<std::uint32_t>(mesh.from_vertex_handle(h).idx());
    const auto b = static_cast<std::uint32_t>(mesh.to_vertex_handle(h).idx());
    arrays.edges.push_back(a);
    arrays.edges.push_back(b);
    const float length = glm::length(arrays.positions[a] - arrays.positions[b]);
    arrays.vertex_edge_lengths[a] += length;
    arrays.vertex_edge_lengths[b] += length;
    ++valence[a];
    ++valence[b];
  }
  for (std::size_t v = 0; v < n_vertices; ++v) {
    if (valence[v] > 0) arrays.vertex_edge_lengths[v] /= static_cast<float>(valence[v]);
  }
  return arrays;
}

std::vector<BoundarySegment> boundary_segments(const Mesh& mesh, const std::vector<Hole>& holes) {
  std::vector<BoundarySegment> segments;
  for (const auto& hole : holes) {
    if (hole.halfedges.empty() || !mesh.is_boundary(hole.halfedges.front())) continue;
    for (const auto h : hole.halfedges) {
      segments.push_back({to_glm(mesh.point(mesh.from_vertex_handle(h))),
                          to_glm(mesh.point(mesh.to_vertex_handle(h))), hole.id});
    }
  }
  return segments;
}

std::vector<glm::vec3> boundary_points(const Mesh& mesh, const Hole& hole) {
  std::vector<glm::vec3> points;
  points.reserve(hole.vertices.size());
  for (const auto v : hole.vertices) points.push_back(to_glm(mesh.point(v)));
  return points;
}

glm::vec3 hole_view_direction(const Mesh& mesh, const Hole& hole) {
  glm::vec3 sum(0.0f), twice_area(0.0f);
  std::size_t faces = 0;
  for (const auto h : hole.halfedges) {
    const FaceHandle outside = mesh.opposite_face_handle(h);
    if (outside.is_valid()) {
      sum += to_glm(mesh.calc_face_normal(outside));
      ++faces;
    }
    twice_area += glm::cross(to_glm(mesh.point(mesh.from_vertex_handle(h))),
                             to_glm(mesh.point(mesh.to_vertex_handle(h))));
  }
  // Around a cut through a tube the normals point every way and cancel: look from the side,
  // across the loop's axis, where the gap shows.
  if (glm::length(sum) < 0.25f * static_cast<float>(faces) && glm::length(twice_area) > 0.0f) {
    const glm::vec3 axis = glm::normalize(twice_area);
    const glm::vec3 other = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(axis, other));
  }
  const float length = glm::length(sum);
  return length > 1e-6f ? sum / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

}  // namespace holefill::viewer
