#include "refine_reference.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <sstream>

#include "patch_face_set.h"

namespace holefill::testing {
namespace {

double angle_at(const Point& corner, const Point& a, const Point& b) {
  const Point u = a - corner, v = b - corner;
  return std::atan2(OpenMesh::cross(u, v).norm(), OpenMesh::dot(u, v));
}

bool swappable(const Mesh& mesh, const detail::PatchFaceSet& patch_faces, EdgeHandle e) {
  const auto h0 = mesh.halfedge_handle(e, 0), h1 = mesh.halfedge_handle(e, 1);
  if (!patch_faces.contains(mesh.face_handle(h0)) || !patch_faces.contains(mesh.face_handle(h1))) {
    return false;
  }
  const Point& a = mesh.point(mesh.from_vertex_handle(h0));
  const Point& b = mesh.point(mesh.to_vertex_handle(h0));
  const Point& c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
  const Point& d = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
  return swap_by_angles(a, b, c, d) && mesh.is_flip_ok(e);
}

constexpr int kMaxRelaxSweeps = 100;
constexpr int kMaxRefineRounds = 200;

std::size_t relax_edges(Mesh& mesh, const detail::PatchFaceSet& patch_faces,
                        const std::vector<FaceHandle>& faces) {
  std::size_t swaps = 0;
  for (int sweep = 0; sweep < kMaxRelaxSweeps; ++sweep) {
    std::size_t swapped_now = 0;
    for (const auto f : faces) {
      EdgeHandle edges[3];
      int count = 0;
      for (const auto e : mesh.fe_range(f)) edges[count++] = e;
      for (const auto e : edges) {
        if (swappable(mesh, patch_faces, e)) {
          mesh.flip(e);
          ++swapped_now;
        }
      }
    }
    swaps += swapped_now;
    if (swapped_now == 0) break;
  }
  return swaps;
}

std::size_t vertex_cap(Mesh& mesh, const Patch& patch, double max_density) {
  PatchTags tags(mesh);
  double area = 0.0, scale = 0.0;
  for (const auto f : patch.faces) area += mesh.calc_face_area(f);
  for (const auto v : patch.boundary) scale += mesh.property(tags.scale, v);
  scale /= static_cast<double>(std::max<std::size_t>(1, patch.boundary.size()));
  const double cap = max_density * area / (scale * scale);
  if (!(max_density > 0.0) || !(cap < 1e15)) return 0;
  return std::max<std::size_t>(static_cast<std::size_t>(std::ceil(cap)), patch.boundary.size());
}

// One centroid split of f when tau calls for it, with the swaps of f's old edges after it.
bool split_face(Mesh& mesh, Patch& patch, detail::PatchFaceSet& patch_faces, FaceHandle f,
                double tau, RefineResult& result) {
  PatchTags tags(mesh);
  VertexHandle corner[3];
  int c = 0;
  for (const auto v : mesh.fv_range(f)) corner[c++] = v;
  const Point centroid =
      (mesh.point(corner[0]) + mesh.point(corner[1]) + mesh.point(corner[2])) / 3.0;
  const double centroid_scale =
      (mesh.property(tags.scale, corner[0]) + mesh.property(tags.scale, corner[1]) +
       mesh.property(tags.scale, corner[2])) /
      3.0;
  bool split = true;
  for (const auto v : corner) {
    const double reach = tau * (centroid - mesh.point(v)).norm();
    if (!(reach > centroid_scale && reach > mesh.property(tags.scale, v))) split = false;
  }
  if (!split) return false;
  std::vector<EdgeHandle> old_edges;
  for (const auto e : mesh.fe_range(f)) old_edges.push_back(e);
  const VertexHandle center = mesh.add_vertex(centroid);
  mesh.split(f, center);
  mesh.property(tags.scale, center) = centroid_scale;
  mesh.property(tags.vertex_stage, center) = static_cast<std::uint8_t>(Stage::Refined);
  patch.new_vertices.push_back(center);
  for (const auto nf : mesh.vf_range(center)) {
    if (patch_faces.insert(nf)) patch.faces.push_back(nf);
    mesh.property(tags.face_stage, nf) = static_cast<std::uint8_t>(Stage::Refined);
  }
  for (const auto e : old_edges) {
    if (swappable(mesh, patch_faces, e)) {
      mesh.flip(e);
      ++result.swaps;
    }
  }
  return true;
}

}  // namespace

bool swap_by_angles(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double now = angle_at(c, a, b) + angle_at(d, a, b);
  const double swapped = angle_at(a, c, d) + angle_at(b, c, d);
  return now > std::numbers::pi + 1e-9 && swapped < now - 1e-9;
}

std::size_t reference_relax_patch_edges(Mesh& mesh, const Patch& patch) {
  return relax_edges(mesh, detail::PatchFaceSet(patch), patch.faces);
}

RefineResult reference_refine_patch(Mesh& mesh, Patch& patch, const RefineOptions& options) {
  RefineResult result;
  assign_boundary_scales(mesh, patch);
  detail::PatchFaceSet patch_faces(patch);
  result.vertex_cap = vertex_cap(mesh, patch, options.max_density);
  for (int round = 0; round < kMaxRefineRounds; ++round) {
    std::size_t splits_now = 0;
    const std::vector<FaceHandle> faces = patch.faces;
    for (const auto f : faces) {
      if (patch.faces.size() + 2 > options.max_patch_faces) {
        result.stopped_at_face_limit = true;
        break;
      }
      if (result.vertex_cap && patch.new_vertices.size() >= result.vertex_cap) {
        result.stopped_at_vertex_cap = true;
        break;
      }
      if (split_face(mesh, patch, patch_faces, f, options.tau, result)) ++splits_now;
    }
    result.splits += splits_now;
    if (splits_now == 0 || result.stopped_at_face_limit) break;
    result.swaps += relax_edges(mesh, patch_faces, patch.faces);
    if (result.stopped_at_vertex_cap) break;
  }
  return result;
}

namespace {

// What differs between the two meshes' connectivity, "" when nothing does.
std::string first_link_difference(const Mesh& expected, const Mesh& actual) {
  std::ostringstream out;
  for (const auto h : expected.halfedges()) {
    if (expected.next_halfedge_handle(h) != actual.next_halfedge_handle(h) ||
        expected.to_vertex_handle(h) != actual.to_vertex_handle(h) ||
        expected.face_handle(h) != actual.face_handle(h)) {
      out << "halfedge " << h.idx() << ": next " << expected.next_halfedge_handle(h).idx() << " / "
          << actual.next_halfedge_handle(h).idx() << ", to " << expected.to_vertex_handle(h).idx()
          << " / " << actual.to_vertex_handle(h).idx() << ", face " << expected.face_handle(h).idx()
          << " / " << actual.face_handle(h).idx();
      return out.str();
    }
  }
  for (const auto f : expected.faces()) {
    if (expected.halfedge_handle(f) != actual.halfedge_handle(f)) {
      out << "face " << f.idx() << "'s halfedge " << expected.halfedge_handle(f).idx() << " / "
          << actual.halfedge_handle(f).idx();
      return out.str();
    }
  }
  for (const auto v : expected.vertices()) {
    if (expected.halfedge_handle(v) != actual.halfedge_handle(v)) {
      out << "vertex " << v.idx() << "'s halfedge " << expected.halfedge_handle(v).idx() << " / "
          << actual.halfedge_handle(v).idx();
      return out.str();
    }
  }
  return "";
}

// An element's status flags, 0 on a mesh without them.
unsigned int status_bits(const Mesh& mesh, VertexHandle v) {
  return mesh.has_vertex_status() ? mesh.status(v).bits() : 0;
}
unsigned int status_bits(const Mesh& mesh, FaceHandle f) {
  return mesh.has_face_status() ? mesh.status(f).bits() : 0;
}

}  // namespace

std::string first_difference(Mesh& expected, Mesh& actual) {
  std::ostringstream out;
  if (expected.n_vertices() != actual.n_vertices() || expected.n_edges() != actual.n_edges() ||
      expected.n_faces() != actual.n_faces()) {
    out << "counts (vertices, edges, faces): " << expected.n_vertices() << ", "
        << expected.n_edges() << ", " << expected.n_faces() << " / " << actual.n_vertices() << ", "
        << actual.n_edges() << ", " << actual.n_faces();
    return out.str();
  }
  const std::string links = first_link_difference(expected, actual);
  if (!links.empty()) return links;
  const PatchTags want(expected), got(actual);
  for (const auto v : expected.vertices()) {
    const Point& p = expected.point(v);
    const Point& q = actual.point(v);
    if (std::memcmp(p.data(), q.data(), sizeof(Point)) != 0 ||
        status_bits(expected, v) != status_bits(actual, v) ||
        expected.property(want.vertex_stage, v) != actual.property(got.vertex_stage, v) ||
        std::memcmp(&expected.property(want.scale, v), &actual.property(got.scale, v),
                    sizeof(double)) != 0) {
      return "vertex " + std::to_string(v.idx()) + "'s position, status, stage or scale";
    }
  }
  for (const auto f : expected.faces()) {
    if (status_bits(expected, f) != status_bits(actual, f) ||
        expected.property(want.face_stage, f) != actual.property(got.face_stage, f)) {
      return "face " + std::to_string(f.idx()) + "'s status or stage";
    }
  }
  return "";
}

}  // namespace holefill::testing
