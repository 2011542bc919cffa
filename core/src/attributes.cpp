#include "holefill/attributes.h"

#include <algorithm>
#include <cmath>
#include <map>

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

// Harmonic values on the new vertices (the umbrella operator's fixed point, boundary values
// fixed), by Gauss-Seidel sweeps from the mean of the boundary.
void interpolate_harmonically(Mesh& mesh, const Patch& patch,
                              const std::vector<OpenMesh::VPropHandleT<double>>& scalars) {
  if (scalars.empty() || patch.new_vertices.empty()) return;
  for (const auto property : scalars) {
    double sum = 0.0;
    for (const auto v : patch.boundary) sum += mesh.property(property, v);
    const double mean =
        patch.boundary.empty() ? 0.0 : sum / static_cast<double>(patch.boundary.size());
    for (const auto v : patch.new_vertices) mesh.property(property, v) = mean;
  }
  constexpr int kMaxSweeps = 500;
  constexpr double kTolerance = 1e-9;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    double change = 0.0;
    for (const auto v : patch.new_vertices) {
      for (const auto property : scalars) {
        double sum = 0.0;
        int count = 0;
        for (const auto neighbour : mesh.vv_range(v)) {
          sum += mesh.property(property, neighbour);
          ++count;
        }
        if (count == 0) continue;
        double& value = mesh.property(property, v);
        const double updated = sum / count;
        change = std::max(change, std::abs(updated - value) / (1.0 + std::abs(updated)));
        value = updated;
      }
    }
    if (change < kTolerance) break;
  }
}

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

// Each patch face takes the value most original faces along the hole have (ties: the smallest).
void take_majority_of_neighbours(Mesh& mesh, const Patch& patch,
                                 OpenMesh::FPropHandleT<double> property) {
  std::map<double, int> votes;
  for (std::size_t i = 0; i < patch.boundary.size(); ++i) {
    const VertexHandle from = patch.boundary[i];
    const VertexHandle to = patch.boundary[(i + 1) % patch.boundary.size()];
    const HalfedgeHandle h = mesh.find_halfedge(from, to);
    if (!h.is_valid()) continue;
    for (const auto side : {h, mesh.opposite_halfedge_handle(h)}) {
      const FaceHandle face = mesh.face_handle(side);
      if (face.is_valid() && face_stage(mesh, face) == Stage::Original) {
        ++votes[mesh.property(property, face)];
      }
    }
  }
  if (votes.empty()) return;
  const auto winner = std::max_element(
      votes.begin(), votes.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  for (const auto f : patch.faces) mesh.property(property, f) = winner->first;
}

}  // namespace

AttributeLayout attribute_layout(const Mesh& mesh) {
  OpenMesh::MPropHandleT<AttributeLayout> handle;
  if (!mesh.get_property_handle(handle, kLayoutName)) return {};
  return mesh.property(handle);
}

void set_attribute_layout(Mesh& mesh, const AttributeLayout& layout) {
  OpenMesh::MPropHandleT<AttributeLayout> handle;
  if (!mesh.get_property_handle(handle, kLayoutName)) mesh.add_property(handle, kLayoutName);
  mesh.property(handle) = layout;
  for (const auto& attribute : layout.vertex) {
    OpenMesh::VPropHandleT<double> property;
    if (!mesh.get_property_handle(property, vertex_property_name(attribute.name))) {
      mesh.add_property(property, vertex_property_name(attribute.name));
    }
  }
  for (const auto& attribute : layout.face) {
    OpenMesh::FPropHandleT<double> property;
    if (!mesh.get_property_handle(property, face_property_name(attribute.name))) {
      mesh.add_property(property, face_property_name(attribute.name));
    }
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

void interpolate_patch_attributes(Mesh& mesh, const Patch& patch) {
  const AttributeLayout layout = attribute_layout(mesh);
  if (layout.empty()) return;
  std::vector<OpenMesh::VPropHandleT<double>> scalars;
  std::array<OpenMesh::VPropHandleT<double>, 3> normal;
  bool has_normals = true;
  for (const auto& attribute : layout.vertex) {
    if (!is_normal(attribute.name)) scalars.push_back(vertex_attribute(mesh, attribute.name));
  }
  for (int axis = 0; axis < 3; ++axis) {
    normal[axis] = vertex_attribute(mesh, std::string("n") + static_cast<char>('x' + axis));
    has_normals = has_normals && normal[axis].is_valid();
  }
  interpolate_harmonically(mesh, patch, scalars);
  if (has_normals) recompute_normals(mesh, patch, normal);
  for (const auto& attribute : layout.face) {
    take_majority_of_neighbours(mesh, patch, face_attribute(mesh, attribute.name));
  }
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
