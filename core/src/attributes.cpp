#include "holefill/attributes.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "holefill/obj_attributes.h"
#include "patch_values.h"

namespace holefill {
namespace {

constexpr const char* kLayoutName = "holefill:attributes";

std::string vertex_property_name(const std::string& name) { return "holefill:v:" + name; }
std::string face_property_name(const std::string& name) { return "holefill:f:" + name; }

bool is_normal(const std::string& name) { return name == "nx" || name == "ny" || name == "nz"; }

}  // namespace

double full_intensity(ScalarType type) {
  switch (type) {
    case ScalarType::Int8:
      return 127.0;
    case ScalarType::UInt8:
      return 255.0;
    case ScalarType::Int16:
      return 32767.0;
    case ScalarType::UInt16:
      return 65535.0;
    case ScalarType::Int32:
      return 2147483647.0;
    case ScalarType::UInt32:
      return 4294967295.0;
    case ScalarType::Float32:
    case ScalarType::Float64:
      break;
  }
  return 1.0;
}

namespace {

void recompute_normals(Mesh& mesh, const Patch& patch,
                       const std::array<OpenMesh::VPropHandleT<double>, 3>& normal) {
  for (const auto v : patch.new_vertices) {
    Point sum(0.0, 0.0, 0.0);
    for (const auto f : mesh.vf_range(v)) sum += mesh.calc_face_normal(f);
    const double length = sum.norm();
    if (length > 0.0) sum /= length;
    for (int axis = 0; axis < 3; ++axis) mesh.property(normal[axis], v) = sum[axis];
  }
}

}  // namespace

AttributeLayout attribute_layout(const Mesh& mesh) {
  OpenMesh::MPropHandleT<AttributeLayout> handle;
  if (!mesh.get_property_handle(handle, kLayoutName)) return {};
  return mesh.property(handle);
}

namespace {

// The index of each double property among `properties` by name, in one pass: OpenMesh finds a
// property by name by passing over all of them, and a pass an attribute grew with the square of
// their number (20,000 PLY properties: 4 s).
std::unordered_map<std::string, int> double_properties(Mesh::const_prop_iterator begin,
                                                       Mesh::const_prop_iterator end) {
  std::unordered_map<std::string, int> found;
  for (int index = 0; begin != end; ++begin, ++index) {
    if (dynamic_cast<const OpenMesh::PropertyT<double>*>(*begin)) found[(*begin)->name()] = index;
  }
  return found;
}

// The handle of each attribute's property, named by `property_name`; invalid where missing.
template <class Handle>
std::vector<Handle> handles_of(const std::unordered_map<std::string, int>& found,
                               const std::vector<ScalarAttribute>& attributes,
                               std::string (*property_name)(const std::string&)) {
  std::vector<Handle> handles;
  handles.reserve(attributes.size());
  for (const auto& attribute : attributes) {
    const auto at = found.find(property_name(attribute.name));
    handles.push_back(at == found.end() ? Handle() : Handle(at->second));
  }
  return handles;
}

}  // namespace

std::vector<OpenMesh::VPropHandleT<double>> vertex_attributes(
    const Mesh& mesh, const std::vector<ScalarAttribute>& attributes) {
  return handles_of<OpenMesh::VPropHandleT<double>>(
      double_properties(mesh.vprops_begin(), mesh.vprops_end()), attributes, vertex_property_name);
}

std::vector<OpenMesh::FPropHandleT<double>> face_attributes(
    const Mesh& mesh, const std::vector<ScalarAttribute>& attributes) {
  return handles_of<OpenMesh::FPropHandleT<double>>(
      double_properties(mesh.fprops_begin(), mesh.fprops_end()), attributes, face_property_name);
}

void set_attribute_layout(Mesh& mesh, const AttributeLayout& layout) {
  OpenMesh::MPropHandleT<AttributeLayout> handle;
  if (!mesh.get_property_handle(handle, kLayoutName)) mesh.add_property(handle, kLayoutName);
  mesh.property(handle) = layout;
  const auto vertex = vertex_attributes(mesh, layout.vertex);
  for (std::size_t a = 0; a < vertex.size(); ++a) {
    OpenMesh::VPropHandleT<double> property;
    if (!vertex[a].is_valid())
      mesh.add_property(property, vertex_property_name(layout.vertex[a].name));
  }
  const auto face = face_attributes(mesh, layout.face);
  for (std::size_t a = 0; a < face.size(); ++a) {
    OpenMesh::FPropHandleT<double> property;
    if (!face[a].is_valid()) mesh.add_property(property, face_property_name(layout.face[a].name));
  }
}

OpenMesh::VPropHandleT<double> vertex_attribute(const Mesh& mesh, const std::string& name) {
  OpenMesh::VPropHandleT<double> property;
  mesh.get_property_handle(property, vertex_property_name(name));
  return property;
}

OpenMesh::FPropHandleT<double> face_attribute(const Mesh& mesh, const std::string& name) {
  OpenMesh::FPropHandleT<double> property;
  mesh.get_property_handle(property, face_property_name(name));
  return property;
}

std::string interpolate_patch_attributes(Mesh& mesh, const Patch& patch) {
  const AttributeLayout layout = attribute_layout(mesh);
  std::vector<OpenMesh::VPropHandleT<double>> scalars;
  std::array<OpenMesh::VPropHandleT<double>, 3> normal;
  bool has_normals = true;
  const auto vertex = vertex_attributes(mesh, layout.vertex);
  for (std::size_t a = 0; a < vertex.size(); ++a) {
    if (!is_normal(layout.vertex[a].name)) scalars.push_back(vertex[a]);
  }
  for (int axis = 0; axis < 3; ++axis) {
    normal[axis] = vertex_attribute(mesh, std::string("n") + static_cast<char>('x' + axis));
    has_normals = has_normals && normal[axis].is_valid();
  }
  detail::interpolate_harmonically(mesh, patch, scalars);
  if (has_normals) recompute_normals(mesh, patch, normal);
  for (const auto face : face_attributes(mesh, layout.face)) {
    detail::take_majority_along_hole(mesh, patch, face);
  }
  return interpolate_patch_obj_attributes(mesh, patch);
}

bool vertex_colors(const Mesh& mesh, std::vector<std::array<float, 3>>& rgb) {
  rgb.clear();
  const AttributeLayout layout = attribute_layout(mesh);
  std::array<OpenMesh::VPropHandleT<double>, 3> channel;
  std::array<double, 3> range{1.0, 1.0, 1.0};
  const char* names[3] = {"red", "green", "blue"};
  for (int c = 0; c < 3; ++c) {
    const auto found = std::find_if(layout.vertex.begin(), layout.vertex.end(),
                                    [&](const ScalarAttribute& a) { return a.name == names[c]; });
    if (found == layout.vertex.end()) return false;
    channel[c] = vertex_attribute(mesh, names[c]);
    range[c] = full_intensity(found->type);
  }
  rgb.resize(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    for (int c = 0; c < 3; ++c) {
      const double value = mesh.property(channel[c], v) / range[c];
      rgb[v.idx()][c] = static_cast<float>(std::clamp(value, 0.0, 1.0));
    }
  }
  return true;
}

}  // namespace holefill
