#include "holefill/mesh_arrays.h"
#include "soup.h"
#include "soup_to_mesh.h"

namespace holefill {
namespace {

void check_columns(const std::vector<std::vector<double>>& columns,
                   const std::vector<ScalarAttribute>& names, std::size_t count, const char* what,
                   const std::string& name) {
  if (columns.size() != names.size()) {
    throw InvalidMeshError(name, std::string(what) +
                                     " attributes: " + std::to_string(names.size()) +
                                     " names but " + std::to_string(columns.size()) + " columns");
  }
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].size() == count) continue;
    throw InvalidMeshError(name, std::string(what) + " attribute '" + names[c].name + "' has " +
                                     std::to_string(columns[c].size()) + " values for " +
                                     std::to_string(count) + " " + what + "s");
  }
}

io::Soup soup_of_arrays(MeshArrays& arrays, const std::string& name) {
  const std::size_t n = arrays.positions.size();
  if (static_cast<long long>(n) > io::kMaxVertices) {
    throw InvalidMeshError(name,
                           "has " + std::to_string(n) + " vertices, more than holefill takes");
  }
  for (std::size_t v = 0; v < n; ++v) io::require_finite(arrays.positions[v], v, 0, name);
  check_columns(arrays.vertex_values, arrays.layout.vertex, n, "vertex", name);
  check_columns(arrays.face_values, arrays.layout.face, arrays.triangles.size(), "face", name);
  io::Soup soup;
  soup.corners.reserve(3 * arrays.triangles.size());
  soup.face_end.reserve(arrays.triangles.size());
  for (std::size_t f = 0; f < arrays.triangles.size(); ++f) {
    for (const std::int64_t index : arrays.triangles[f]) {
      if (index < 0 || static_cast<std::size_t>(index) >= n) {
        throw InvalidMeshError(name, "face " + std::to_string(f) + " uses vertex " +
                                         std::to_string(index) + ", not one of the " +
                                         std::to_string(n) + " vertices");
      }
      soup.corners.push_back(static_cast<int>(index));
    }
    soup.face_end.push_back(soup.corners.size());
  }
  std::vector<std::array<std::int64_t, 3>>().swap(arrays.triangles);
  soup.positions = std::move(arrays.positions);
  soup.layout = std::move(arrays.layout);
  soup.vertex_values = std::move(arrays.vertex_values);
  soup.face_values = std::move(arrays.face_values);
  return soup;
}

}  // namespace

Mesh mesh_from_arrays(MeshArrays arrays, const std::string& name, LoadReport* report) {
  LoadReport local;
  LoadReport& out = report ? *report : local;
  out = LoadReport{};
  out.format = "arrays";
  Mesh mesh = io::build_mesh(soup_of_arrays(arrays, name), out);
  if (mesh.n_faces() == 0) throw InvalidMeshError(name, "contains no faces");
  io::add_warnings(out);
  return mesh;
}

}  // namespace holefill
