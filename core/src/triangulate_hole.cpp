#include <algorithm>
#include <array>
#include <new>
#include <optional>
#include <unordered_map>

#include "coincident_vertices.h"
#include "deletion_flags.h"
#include "hole_triangulation.h"
#include "vertex_link.h"

namespace holefill::detail {

HolePolygon hole_polygon(const Mesh& mesh, const Hole& hole) {
  HolePolygon polygon;
  const int n = static_cast<int>(hole.vertices.size());
  std::unordered_map<int, std::vector<int>> positions_of_vertex;
  for (int i = 0; i < n; ++i) {
    polygon.points.push_back(mesh.point(hole.vertices[i]));
    // An invalid halfedge is a bridge between two loops (bridge.h): nothing lies across it.
    const FaceHandle outside =
        hole.halfedges[i].is_valid() ? mesh.opposite_face_handle(hole.halfedges[i]) : FaceHandle();
    polygon.outside_normals.push_back(outside.is_valid() ? mesh.calc_face_normal(outside)
                                                         : Point(0.0, 0.0, 0.0));
    positions_of_vertex[hole.vertices[i].idx()].push_back(i);
  }
  auto adjacent = [n](int a, int b) {
    const int d = std::abs(a - b);
    return d == 1 || d == n - 1;
  };
  for (int i = 0; i < n; ++i) {
    for (const int j : positions_of_vertex[hole.vertices[i].idx()]) {
      if (i < j) polygon.forbidden_chords.emplace_back(i, j);
    }
    for (const auto neighbour : mesh.vv_range(hole.vertices[i])) {
      const auto found = positions_of_vertex.find(neighbour.idx());
      if (found == positions_of_vertex.end()) continue;
      for (const int k : found->second) {
        if (i < k && !adjacent(i, k)) polygon.forbidden_chords.emplace_back(i, k);
      }
    }
  }
  return polygon;
}

namespace {

// The hole is the far side of one lone triangle: its three boundary edges all border one face.
bool is_back_of_lone_triangle(const Mesh& mesh, const Hole& hole) {
  if (hole.size() != 3) return false;
  const FaceHandle face = mesh.opposite_face_handle(hole.halfedges[0]);
  return face.is_valid() && face == mesh.opposite_face_handle(hole.halfedges[1]) &&
         face == mesh.opposite_face_handle(hole.halfedges[2]);
}

// ---- Pinched loops: a loop passing more than once through one vertex X is triangulated as a
// polygon whose passes are corners of their own (no chord joins two of them). OpenMesh links the
// boundary around X into one rotation cycle, so each pass runs from the side of one fan of faces
// around X to the side of another: the patch's triangles at each pass fill the gap between two
// fans, and together they join every fan into one. (Splitting the loop at X would instead make
// each part the back of one fan, and close it on itself.)

// The first vertex the loop passes more than once that the patch `triangles` (positions of the
// hole, oriented like it) would not leave with one fan of faces; -1 when there is none.
int vertex_left_pinched(const Mesh& mesh, const Hole& hole,
                        const std::vector<std::array<int, 3>>& triangles) {
  std::unordered_map<int, int> passes;
  for (const auto v : hole.vertices) ++passes[v.idx()];
  std::unordered_map<int, std::vector<std::pair<int, int>>> links;
  for (const auto& [v, count] : passes) {
    if (count > 1)
      detail::add_link_edges(
          mesh, VertexHandle(v), [](int u) { return u; }, links[v]);
  }
  for (const auto& t : triangles) {
    for (int c = 0; c < 3; ++c) {
      const auto link = links.find(hole.vertices[t[c]].idx());
      if (link == links.end()) continue;
      link->second.emplace_back(hole.vertices[t[(c + 1) % 3]].idx(),
                                hole.vertices[t[(c + 2) % 3]].idx());
    }
  }
  for (const auto& [v, link] : links) {
    if (!detail::is_one_fan(link)) return v;
  }
  return -1;
}

}  // namespace

PlannedTriangulation plan_triangulation(const Mesh& mesh, const Hole& hole,
                                        const TriangulateOptions& options) {
  PlannedTriangulation result;
  if (hole.size() < 3) {
    result.failure = {FailureKind::TooFewEdges,
                      "a boundary loop of fewer than 3 edges cannot be triangulated"};
    return result;
  }
  const bool restricted =
      options.restricted.above_edges > 0 && hole.size() > options.restricted.above_edges;
  if (hole.size() >= kMaxPolygonSize) {
    result.failure = {FailureKind::TooManyEdges,
                      "the hole has " + std::to_string(hole.size()) +
                          " boundary edges, more than the dynamic program can index (at most " +
                          std::to_string(kMaxPolygonSize - 1) +
                          ", the restricted search for large holes included); leave it out of the "
                          "selection by a limit on boundary edges"};
    return result;
  }
  if (hole.size() > kMaxFullSearchEdges && !restricted) {
    result.failure = {FailureKind::TooManyEdges,
                      "the hole has " + std::to_string(hole.size()) +
                          " boundary edges, too many for the full dynamic program (at most " +
                          std::to_string(std::min(kMaxFullSearchEdges, kMaxPolygonSize - 1)) +
                          ": its time grows with the cube of the edge count); leave it out of the "
                          "selection by a limit on boundary edges"};
    return result;
  }
  std::unordered_map<int, int> seen;
  int most_passes = 0, busiest = -1;
  for (const auto v : hole.vertices) {
    if (const int passes = ++seen[v.idx()]; passes > most_passes) {
      most_passes = passes;
      busiest = v.idx();
    }
  }
  const bool pinched = most_passes > 1;
  if (most_passes > kMaxVertexPasses) {
    result.failure = {FailureKind::VertexPassedTooOften,
                      "its boundary passes through vertex " + std::to_string(busiest + 1) + " " +
                          std::to_string(seen[busiest]) + " times, more than the " +
                          std::to_string(kMaxVertexPasses) +
                          " a patch is planned for (kMaxVertexPasses): it runs around pieces that "
                          "meet only there, not around a hole"};
    return result;
  }
  if (const auto twins = detail::coincident_vertices(mesh, hole)) {
    result.failure = {
        FailureKind::CoincidentPoints,
        "its boundary passes twice through one position (vertices " +
            std::to_string(twins->first + 1) + " and " + std::to_string(twins->second + 1) +
            " lie at the same place): a zero-width crack or an unwelded seam, which a "
            "patch could only cover with triangles of zero width"};
    return result;
  }
  if (is_back_of_lone_triangle(mesh, hole)) {
    result.failure = {FailureKind::BackOfLoneTriangle,
                      "it is the back of a lone triangle (face " +
                          std::to_string(mesh.opposite_face_handle(hole.halfedges[0]).idx() + 1) +
                          "); filling it would only cover that face with a copy of itself"};
    return result;
  }
  try {
    result.triangulation = triangulate_polygon(hole_polygon(mesh, hole), options);
  } catch (const std::bad_alloc&) {
    result.failure = {FailureKind::OutOfMemory, "not enough memory to triangulate it"};
    return result;
  }
  if (!result.triangulation) {
    result.failure = {
        FailureKind::NoTriangulation,
        hole.size() > kMaxFullSearchEdges
            ? "the restricted search for large holes found no valid triangulation, and the hole "
              "has too many edges for the full one (more than " +
                  std::to_string(kMaxFullSearchEdges) + ")"
            : "no valid triangulation: every one would duplicate an edge that already exists"};
  } else if (result.triangulation->quality.degenerate > 0) {
    result.triangulation.reset();
    result.failure = {
        FailureKind::DegenerateTriangle,
        "its triangulation would have a degenerate (zero-area) triangle: its boundary has "
        "collinear or coincident points"};
  } else if (const int v =
                 pinched ? vertex_left_pinched(mesh, hole, result.triangulation->triangles) : -1;
             v >= 0) {
    result.triangulation.reset();
    result.failure = {FailureKind::LeftPinched,
                      "its boundary passes more than once through vertex " + std::to_string(v + 1) +
                          ", and its patch would not join the fans of faces there into one"};
  }
  return result;
}

TriangulateHoleResult apply_triangulation(Mesh& mesh, const Hole& hole,
                                          const PlannedTriangulation& plan) {
  TriangulateHoleResult result;
  if (!plan.triangulation) {
    result.failure = plan.failure;
    return result;
  }
  PatchTags tags(mesh);
  Patch patch;
  patch.hole_id = hole.id;
  patch.stage = Stage::Triangulated;
  patch.boundary = hole.vertices;
  for (const auto& t : plan.triangulation->triangles) {
    const FaceHandle face =
        mesh.add_face(hole.vertices[t[0]], hole.vertices[t[1]], hole.vertices[t[2]]);
    if (!face.is_valid()) {
      // The topology around the loop (e.g. a pinched vertex) refused a triangle: take back the
      // ones added so far. They are the newest elements, so garbage collection moves no others.
      const detail::DeletionFlags flags(mesh);
      for (const auto added : patch.faces) mesh.delete_face(added, false);
      mesh.garbage_collection();
      result.failure = {FailureKind::MeshRefusedTriangle,
                        "the mesh around this hole refused a patch triangle (non-manifold vertex)"};
      return result;
    }
    mesh.property(tags.face_stage, face) = static_cast<std::uint8_t>(Stage::Triangulated);
    patch.faces.push_back(face);
  }
  result.patch = std::move(patch);
  return result;
}

}  // namespace holefill::detail
