#include "holefill/obj_attributes.h"

#include <bit>
#include <optional>
#include <string_view>

#include "patch_values.h"
#include "property_handles.h"

namespace holefill {
namespace {

constexpr const char* kTables = "holefill:obj";
constexpr const char* kTexcoord = "holefill:obj:texcoord";
constexpr const char* kNormal = "holefill:obj:normal";
constexpr const char* kMaterial = "holefill:obj:material";
constexpr const char* kGroup = "holefill:obj:group";
constexpr const char* kObject = "holefill:obj:object";
constexpr const char* kSmoothing = "holefill:obj:smoothing";

// The vertices of the patch's faces that the patch did not add (the hole's loops): their
// values are fixed.
std::vector<VertexHandle> fixed_vertices(const Mesh& mesh, const Patch& patch) {
  std::vector<char> is_new(mesh.n_vertices(), 0), seen(mesh.n_vertices(), 0);
  for (const auto v : patch.new_vertices) is_new[v.idx()] = 1;
  std::vector<VertexHandle> fixed;
  for (const auto f : patch.faces) {
    for (const auto v : mesh.fv_range(f)) {
      if (is_new[v.idx()] || seen[v.idx()]) continue;
      seen[v.idx()] = 1;
      fixed.push_back(v);
    }
  }
  return fixed;
}

// The numbers (texture coordinate or normal) on a vertex's corners in original faces.
struct CornerNumbers {
  int first = 0;           // of the first corner that has one
  bool missing = false;    // some corner has none
  bool different = false;  // corners have different values
};

template <class Same>
CornerNumbers original_corner_numbers(const Mesh& mesh, VertexHandle v,
                                      OpenMesh::HPropHandleT<int> property, Same&& same) {
  CornerNumbers numbers;
  for (const auto h : mesh.vih_range(v)) {
    const FaceHandle face = mesh.face_handle(h);
    if (!face.is_valid() || face_stage(mesh, face) != Stage::Original) continue;
    const int number = mesh.property(property, h);
    if (number == 0) {
      numbers.missing = true;
    } else if (numbers.first == 0) {
      numbers.first = number;
    } else if (!same(numbers.first, number)) {
      numbers.different = true;
    }
  }
  return numbers;
}

bool same_bits(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  for (int i = 0; i < 3; ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

// Gives every corner of the patch's faces `number_of(vertex)`.
template <class NumberOf>
void set_patch_corners(Mesh& mesh, const Patch& patch, OpenMesh::HPropHandleT<int> property,
                       NumberOf&& number_of) {
  for (const auto f : patch.faces) {
    for (const auto h : mesh.fh_range(f)) {
      mesh.property(property, h) = number_of(mesh.to_vertex_handle(h));
    }
  }
}

// The texture coordinate number of each fixed vertex when the hole's boundary lies in one chart
// (each has one texture coordinate on its original faces); otherwise nothing, and `why` says
// which vertex breaks it. Vertices are indexed by idx().
std::optional<std::vector<int>> one_chart(const Mesh& mesh, const ObjHandles& obj,
                                          const std::vector<VertexHandle>& fixed,
                                          std::string& why) {
  const ObjTables& tables = mesh.property(obj.tables);
  std::vector<int> number(mesh.n_vertices(), 0);
  for (const auto v : fixed) {
    const CornerNumbers found = original_corner_numbers(mesh, v, obj.texcoord, [&](int a, int b) {
      return a == b || same_bits(tables.texcoords[a - 1], tables.texcoords[b - 1]);
    });
    if (found.first == 0 || found.missing || found.different) {
      why = "vertex " + std::to_string(v.idx()) +
            (found.different ? " lies on a UV seam (it has several texture coordinates)"
                             : " has a corner without a texture coordinate");
      return std::nullopt;
    }
    number[v.idx()] = found.first;
  }
  return number;
}

// Interpolates u, v (and w) harmonically over the patch from its fixed vertices' texture
// coordinates, as colours are; each new vertex gets a new entry in the table.
void interpolate_texcoords(Mesh& mesh, const Patch& patch, const ObjHandles& obj,
                           const std::vector<VertexHandle>& fixed, std::vector<int>& number) {
  std::vector<OpenMesh::VPropHandleT<double>> uvw(3);
  for (auto& property : uvw) mesh.add_property(property);
  ObjTables& tables = mesh.property(obj.tables);
  for (const auto v : fixed) {
    for (int i = 0; i < 3; ++i) mesh.property(uvw[i], v) = tables.texcoords[number[v.idx()] - 1][i];
  }
  detail::interpolate_harmonically(mesh, patch, uvw);
  for (const auto v : patch.new_vertices) {
    tables.texcoords.push_back(
        {mesh.property(uvw[0], v), mesh.property(uvw[1], v), mesh.property(uvw[2], v)});
    number[v.idx()] = static_cast<int>(tables.texcoords.size());
  }
  for (auto& property : uvw) mesh.remove_property(property);
  set_patch_corners(mesh, patch, obj.texcoord, [&](VertexHandle v) { return number[v.idx()]; });
}

// Corner normals of the patch: a fixed vertex whose original corners share one normal keeps it
// (smooth shading goes on across the boundary); other vertices get a new one, the mean of the
// normals of the patch's faces around them (a boundary vertex on a hard edge stays hard).
void recompute_corner_normals(Mesh& mesh, const Patch& patch, const ObjHandles& obj,
                              const std::vector<VertexHandle>& fixed) {
  std::vector<int> number(mesh.n_vertices(), 0);
  ObjTables& tables = mesh.property(obj.tables);
  auto add_geometric_normal = [&](VertexHandle v) {
    Point sum(0.0, 0.0, 0.0);
    for (const auto f : mesh.vf_range(v)) {
      if (face_stage(mesh, f) != Stage::Original) sum += mesh.calc_face_normal(f);
    }
    const double length = sum.norm();
    tables.normals.push_back(length > 0.0 ? sum / length : sum);
    number[v.idx()] = static_cast<int>(tables.normals.size());
  };
  for (const auto v : fixed) {
    const CornerNumbers found =
        original_corner_numbers(mesh, v, obj.normal, [](int a, int b) { return a == b; });
    if (found.first != 0 && !found.missing && !found.different) {
      number[v.idx()] = found.first;
    } else {
      add_geometric_normal(v);
    }
  }
  for (const auto v : patch.new_vertices) add_geometric_normal(v);
  set_patch_corners(mesh, patch, obj.normal, [&](VertexHandle v) { return number[v.idx()]; });
}

// Whether any original corner at one of `vertices` has a number in `property`.
bool used_around(const Mesh& mesh, const std::vector<VertexHandle>& vertices,
                 OpenMesh::HPropHandleT<int> property) {
  for (const auto v : vertices) {
    const CornerNumbers found =
        original_corner_numbers(mesh, v, property, [](int, int) { return true; });
    if (found.first != 0) return true;
  }
  return false;
}

}  // namespace

ObjHandles obj_handles(const Mesh& mesh) {
  ObjHandles obj;
  if (!mesh.get_property_handle(obj.tables, kTables)) return ObjHandles();
  mesh.get_property_handle(obj.texcoord, kTexcoord);
  mesh.get_property_handle(obj.normal, kNormal);
  mesh.get_property_handle(obj.material, kMaterial);
  mesh.get_property_handle(obj.group, kGroup);
  mesh.get_property_handle(obj.object, kObject);
  mesh.get_property_handle(obj.smoothing, kSmoothing);
  return obj;
}

ObjHandles add_obj_handles(Mesh& mesh, const ObjFaceNumbers& face_numbers) {
  ObjHandles obj;
  detail::find_or_add_property(mesh, obj.tables, kTables);
  detail::find_or_add_property(mesh, obj.texcoord, kTexcoord);
  detail::find_or_add_property(mesh, obj.normal, kNormal);
  if (face_numbers.material) detail::find_or_add_property(mesh, obj.material, kMaterial);
  if (face_numbers.group) detail::find_or_add_property(mesh, obj.group, kGroup);
  if (face_numbers.object) detail::find_or_add_property(mesh, obj.object, kObject);
  if (face_numbers.smoothing) detail::find_or_add_property(mesh, obj.smoothing, kSmoothing);
  return obj_handles(mesh);  // with the per-face numbers the mesh had already
}

std::string interpolate_patch_obj_attributes(Mesh& mesh, const Patch& patch) {
  const ObjHandles obj = obj_handles(mesh);
  if (!obj.valid() || patch.faces.empty()) return {};
  for (const auto property : {obj.material, obj.group, obj.object, obj.smoothing}) {
    if (property.is_valid()) detail::take_majority_along_hole(mesh, patch, property);
  }
  const std::vector<VertexHandle> fixed = fixed_vertices(mesh, patch);
  std::string note;
  set_patch_corners(mesh, patch, obj.texcoord, [](VertexHandle) { return 0; });
  if (used_around(mesh, fixed, obj.texcoord)) {
    std::string why;
    if (auto number = one_chart(mesh, obj, fixed, why)) {
      interpolate_texcoords(mesh, patch, obj, fixed, *number);
    } else {
      note = "no texture coordinates on the patch: the hole's boundary is not in one UV chart (" +
             why + ")";
    }
  }
  set_patch_corners(mesh, patch, obj.normal, [](VertexHandle) { return 0; });
  if (used_around(mesh, fixed, obj.normal)) recompute_corner_normals(mesh, patch, obj, fixed);
  return note;
}

}  // namespace holefill
