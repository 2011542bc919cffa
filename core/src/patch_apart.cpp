#include "patch_apart.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "deletion_flags.h"
#include "per_hole_fill.h"

namespace holefill::detail {
namespace {

// The surroundings of a hole as a small mesh: the mesh's faces at some vertices, and their
// corners, each added in ascending order so that every order among them is the mesh's.
struct Surroundings {
  Mesh mesh;
  std::vector<int> vertices;  // local vertex i is the mesh's vertices[i]
  bool complete = true;       // false when the small mesh refused a face

  VertexHandle local(VertexHandle v) const {
    const auto at = std::lower_bound(vertices.begin(), vertices.end(), v.idx());
    return VertexHandle(static_cast<int>(at - vertices.begin()));
  }
};

// The polygon's vertices and their neighbours: the vertices whose every face the stages may read.
std::vector<int> fan_vertices_of(const Mesh& mesh, const Hole& polygon) {
  std::vector<int> fans;
  for (const auto v : polygon.vertices) {
    fans.push_back(v.idx());
    for (const auto w : mesh.vv_range(v)) fans.push_back(w.idx());
  }
  std::sort(fans.begin(), fans.end());
  fans.erase(std::unique(fans.begin(), fans.end()), fans.end());
  return fans;
}

Surroundings copy_surroundings(const Mesh& mesh, const std::vector<int>& fans) {
  std::vector<int> faces;
  for (const int v : fans) {
    for (const auto f : mesh.vf_range(VertexHandle(v))) faces.push_back(f.idx());
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  Surroundings copy;
  for (const int f : faces) {
    for (const auto v : mesh.fv_range(FaceHandle(f))) copy.vertices.push_back(v.idx());
  }
  std::sort(copy.vertices.begin(), copy.vertices.end());
  copy.vertices.erase(std::unique(copy.vertices.begin(), copy.vertices.end()), copy.vertices.end());
  copy.mesh.reserve(copy.vertices.size(), 3 * faces.size(), faces.size());
  for (const int v : copy.vertices) copy.mesh.add_vertex(mesh.point(VertexHandle(v)));
  std::vector<VertexHandle> corners;
  for (const int f : faces) {
    corners.clear();
    for (const auto v : mesh.fv_range(FaceHandle(f))) corners.push_back(copy.local(v));
    if (!copy.mesh.add_face(corners).is_valid()) copy.complete = false;
  }
  return copy;
}

// The polygon with the copy's handles; nullopt when a boundary edge is not one there.
std::optional<Hole> local_polygon(const Surroundings& copy, const Hole& polygon) {
  Hole local = polygon;
  for (auto& v : local.vertices) v = copy.local(v);
  for (std::size_t i = 0; i < local.halfedges.size(); ++i) {
    if (!polygon.halfedges[i].is_valid()) continue;  // a bridge
    const auto h =
        copy.mesh.find_halfedge(local.vertices[i], local.vertices[(i + 1) % local.vertices.size()]);
    if (!h.is_valid() || !copy.mesh.is_boundary(h)) return std::nullopt;
    local.halfedges[i] = h;
  }
  return local;
}

// Whether the fill is an ordinary one, whose every message and handle can be taken over: a
// failure, an undone stage or a fallback names elements by the copy's numbers and is rare.
bool ordinary(const HoleFill& fill) {
  return !fill.failed() && fill.smoothing_note.empty() && fill.refinement_note.empty();
}

// Takes the patch out of the copy: new vertices and faces, numbered as PatchApart says; the
// patch's lists keep their order, each element named by its position among the new ones. False
// when the patch is not exactly the copy's newest elements.
bool take_patch(Surroundings& copy, std::size_t old_faces, PatchApart& apart) {
  Mesh& local = copy.mesh;
  const std::size_t old_vertices = copy.vertices.size();
  Patch& patch = apart.fill.patch;
  const bool newest =
      std::all_of(patch.faces.begin(), patch.faces.end(),
                  [&](FaceHandle f) { return static_cast<std::size_t>(f.idx()) >= old_faces; }) &&
      std::all_of(patch.new_vertices.begin(), patch.new_vertices.end(), [&](VertexHandle v) {
        return static_cast<std::size_t>(v.idx()) >= old_vertices;
      });
  if (!newest || local.n_faces() - old_faces != patch.faces.size() ||
      local.n_vertices() - old_vertices != patch.new_vertices.size()) {
    return false;
  }
  const PatchTags tags(local);
  for (std::size_t v = old_vertices; v < local.n_vertices(); ++v) {
    const VertexHandle handle(static_cast<int>(v));
    apart.points.push_back(local.point(handle));
    apart.point_stages.push_back(local.property(tags.vertex_stage, handle));
    apart.point_scales.push_back(local.property(tags.scale, handle));
  }
  for (std::size_t f = old_faces; f < local.n_faces(); ++f) {
    std::array<int, 3> corners{};
    int c = 0;
    for (const auto v : local.fv_range(FaceHandle(static_cast<int>(f)))) {
      const auto i = static_cast<std::size_t>(v.idx());
      corners[c++] = i < old_vertices ? copy.vertices[i] : -1 - static_cast<int>(i - old_vertices);
    }
    apart.triangles.push_back(corners);
    apart.triangle_stages.push_back(
        local.property(tags.face_stage, FaceHandle(static_cast<int>(f))));
  }
  for (auto& v : patch.boundary) {
    apart.boundary_scales.push_back(local.property(tags.scale, v));
    v = VertexHandle(copy.vertices[static_cast<std::size_t>(v.idx())]);
  }
  // The feature lines and continued creases name the copy's vertices too (creases as corners).
  for (auto& line : apart.fill.features.lines) {
    line.vertex = VertexHandle(copy.vertices[static_cast<std::size_t>(line.vertex.idx())]);
  }
  for (auto& chain : apart.fill.creases) {
    for (auto& v : chain) {
      const auto i = static_cast<std::size_t>(v.idx());
      v = VertexHandle(i < old_vertices ? copy.vertices[i]
                                        : -1 - static_cast<int>(i - old_vertices));
    }
  }
  for (auto& f : patch.faces) f = FaceHandle(f.idx() - static_cast<int>(old_faces));
  for (auto& v : patch.new_vertices) v = VertexHandle(v.idx() - static_cast<int>(old_vertices));
  return true;
}

bool finite_box(const Box& box) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!std::isfinite(box.low[axis]) || !std::isfinite(box.high[axis])) return false;
  }
  return true;
}

}  // namespace

PatchApart fill_apart(const Mesh& mesh, const Hole& polygon, const FillOptions& options,
                      const PlannedTriangulation& plan, const MeshFaceIndex& index,
                      const Box& region) {
  PatchApart apart;
  apart.in_mesh = true;
  if (!plan.triangulation || !finite_box(region)) return apart;
  apart.fan_vertices = fan_vertices_of(mesh, polygon);
  Surroundings copy = copy_surroundings(mesh, apart.fan_vertices);
  const auto local = local_polygon(copy, polygon);
  if (!copy.complete || !local) return apart;
  const std::size_t old_faces = copy.mesh.n_faces();
  const MeshFaceIndex around(index, region);
  apart.fill = fill_planned(copy.mesh, *local, options, &plan, &around);
  apart.looked_up = around.looked_up();
  if (around.looked_outside() || !ordinary(apart.fill)) return apart;
  if (!take_patch(copy, old_faces, apart)) return apart;
  apart.in_mesh = false;
  return apart;
}

bool SplicedPatches::reached_by(const PatchApart& apart) const {
  for (const int v : apart.fan_vertices) {
    if (boundary_[static_cast<std::size_t>(v)]) return true;
  }
  return index_.added_overlaps(apart.looked_up);
}

void SplicedPatches::add(const HoleFill& fill) {
  for (const auto v : fill.patch.boundary) {
    if (static_cast<std::size_t>(v.idx()) < boundary_.size()) boundary_[v.idx()] = 1;
  }
}

bool splice_patch(Mesh& mesh, PatchApart& apart) {
  const PatchTags tags(mesh);
  std::vector<VertexHandle> vertices;
  for (std::size_t k = 0; k < apart.points.size(); ++k) {
    const VertexHandle v = mesh.add_vertex(apart.points[k]);
    mesh.property(tags.vertex_stage, v) = apart.point_stages[k];
    mesh.property(tags.scale, v) = apart.point_scales[k];
    vertices.push_back(v);
  }
  auto vertex = [&](int corner) {
    return corner >= 0 ? VertexHandle(corner) : vertices[static_cast<std::size_t>(-1 - corner)];
  };
  std::vector<FaceHandle> faces;
  for (std::size_t k = 0; k < apart.triangles.size(); ++k) {
    const auto& t = apart.triangles[k];
    const FaceHandle face = mesh.add_face(vertex(t[0]), vertex(t[1]), vertex(t[2]));
    if (!face.is_valid()) {
      // Taken back: the newest elements, so garbage collection moves no others.
      const DeletionFlags flags(mesh);
      for (const auto added : faces) mesh.delete_face(added, false);
      for (const auto added : vertices) mesh.delete_vertex(added);
      mesh.garbage_collection();
      return false;
    }
    mesh.property(tags.face_stage, face) = apart.triangle_stages[k];
    faces.push_back(face);
  }
  Patch& patch = apart.fill.patch;
  for (std::size_t i = 0; i < patch.boundary.size(); ++i) {
    mesh.property(tags.scale, patch.boundary[i]) = apart.boundary_scales[i];
  }
  for (auto& f : patch.faces) f = faces[static_cast<std::size_t>(f.idx())];
  for (auto& v : patch.new_vertices) v = vertices[static_cast<std::size_t>(v.idx())];
  for (auto& chain : apart.fill.creases) {
    for (auto& v : chain) v = vertex(v.idx());
  }
  return true;
}

}  // namespace holefill::detail
