#include "soup_attributes.h"

namespace holefill::io {
namespace {

// attributes.h's values: each vertex its source position's, each face its source polygon's.
void copy_layout_values(const Soup& soup, const SoupOrigins& origins, Mesh& mesh) {
  if (soup.layout.empty()) return;
  set_attribute_layout(mesh, soup.layout);
  for (std::size_t a = 0; a < soup.layout.vertex.size(); ++a) {
    const auto property = vertex_attribute(mesh, soup.layout.vertex[a].name);
    for (const auto v : mesh.vertices()) {
      mesh.property(property, v) = soup.vertex_values[a][origins.vertex[v.idx()]];
    }
  }
  for (std::size_t a = 0; a < soup.layout.face.size(); ++a) {
    const auto property = face_attribute(mesh, soup.layout.face[a].name);
    for (const auto f : mesh.faces()) {
      mesh.property(property, f) = soup.face_values[a][origins.face[f.idx()]];
    }
  }
}

bool has_obj_values(const Soup& soup) {
  return has_corner_values(soup) || !soup.face_material.empty() || !soup.face_group.empty() ||
         !soup.face_object.empty() || !soup.face_smoothing.empty() ||
         !soup.obj.material_libraries.empty() || !soup.obj.texcoords.empty() ||
         !soup.obj.normals.empty();
}

// Each halfedge of a face gets the numbers of the soup corner at its end vertex. Written into
// the properties' arrays, the faces being triangles (through OpenMesh's property and circulator
// calls this was about a twentieth of loading a textured OBJ).
void copy_corner_numbers(const Soup& soup, const SoupOrigins& origins, const ObjHandles& obj,
                         Mesh& mesh) {
  std::vector<int>& texcoords = mesh.property(obj.texcoord).data_vector();
  std::vector<int>& normals = mesh.property(obj.normal).data_vector();
  for (const auto f : mesh.faces()) {
    const Triangle& corners = origins.face_corners[f.idx()];
    const Triangle& positions = origins.face_corner_vertices[f.idx()];
    HalfedgeHandle h = mesh.halfedge_handle(f);
    for (int side = 0; side < 3; ++side, h = mesh.next_halfedge_handle(h)) {
      const int position = origins.vertex[mesh.to_vertex_handle(h).idx()];
      const int c = positions[0] == position ? 0 : positions[1] == position ? 1 : 2;
      const auto k = static_cast<std::size_t>(corners[c]);
      const auto at = static_cast<std::size_t>(h.idx());
      if (!soup.corner_texcoord.empty()) texcoords[at] = soup.corner_texcoord[k];
      if (!soup.corner_normal.empty()) normals[at] = soup.corner_normal[k];
    }
  }
}

void copy_obj_values(const Soup& soup, const SoupOrigins& origins, Mesh& mesh) {
  if (!has_obj_values(soup)) return;
  const ObjHandles obj = add_obj_handles(mesh);
  mesh.property(obj.tables) = soup.obj;
  if (has_corner_values(soup)) copy_corner_numbers(soup, origins, obj, mesh);
  const std::pair<const std::vector<int>*, OpenMesh::FPropHandleT<int>> per_face[] = {
      {&soup.face_material, obj.material},
      {&soup.face_group, obj.group},
      {&soup.face_object, obj.object},
      {&soup.face_smoothing, obj.smoothing}};
  for (const auto& [values, property] : per_face) {
    if (values->empty()) continue;
    for (const auto f : mesh.faces()) mesh.property(property, f) = (*values)[origins.face[f.idx()]];
  }
}

}  // namespace

void keep_file_format(const Soup& soup, Mesh& mesh) {
  const AttributeLayout plain;  // ASCII, double positions, uchar counts, int indices
  const AttributeLayout& file = soup.layout;
  if (file.encoding != plain.encoding || file.position_type != plain.position_type ||
      file.face_count_type != plain.face_count_type ||
      file.face_index_type != plain.face_index_type) {
    set_attribute_layout(mesh, file);
  }
}

bool has_corner_values(const Soup& soup) {
  return !soup.corner_texcoord.empty() || !soup.corner_normal.empty();
}

bool has_attributes(const Soup& soup) { return !soup.layout.empty() || has_obj_values(soup); }

void copy_soup_attributes(const Soup& soup, const SoupOrigins& origins, Mesh& mesh) {
  copy_layout_values(soup, origins, mesh);
  copy_obj_values(soup, origins, mesh);
}

}  // namespace holefill::io
