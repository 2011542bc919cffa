#include "soup_attributes.h"

#include "two_threads.h"

namespace holefill::io {
namespace {

// values[origins[i]] for each element i, written into the property's array (each half on its
// own thread when `two`).
template <class T>
void copy_by_origin(const std::vector<T>& values, const std::vector<int>& origins,
                    std::vector<T>& property, bool two) {
  run_in_halves(two, property.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) property[i] = values[origins[i]];
  });
}

// attributes.h's values: each vertex its source position's, each face its source polygon's.
void copy_layout_values(const Soup& soup, const SoupOrigins& origins, Mesh& mesh, bool two) {
  if (soup.layout.empty()) return;
  set_attribute_layout(mesh, soup.layout);
  const auto vertex = vertex_attributes(mesh, soup.layout.vertex);
  for (std::size_t a = 0; a < vertex.size(); ++a) {
    copy_by_origin(soup.vertex_values[a], origins.vertex, mesh.property(vertex[a]).data_vector(),
                   two);
  }
  const auto face = face_attributes(mesh, soup.layout.face);
  for (std::size_t a = 0; a < face.size(); ++a) {
    copy_by_origin(soup.face_values[a], origins.face, mesh.property(face[a]).data_vector(), two);
  }
}

bool has_obj_values(const Soup& soup) {
  return has_corner_values(soup) || !soup.face_material.empty() || !soup.face_group.empty() ||
         !soup.face_object.empty() || !soup.face_smoothing.empty() ||
         !soup.obj.material_libraries.empty() || !soup.obj.texcoords.empty() ||
         !soup.obj.normals.empty();
}

// Each halfedge of a face gets the numbers of the soup corner at its end vertex: the face's c-th
// halfedge from its own, that of its c-th corner. Written into the properties' arrays, the faces
// being triangles (through OpenMesh's property and circulator calls this was about a twentieth of
// loading a textured OBJ). A face's halfedges are its own, so each half of the faces is on its
// own thread when `two`.
void copy_corner_numbers(const Soup& soup, const SoupOrigins& origins, const ObjHandles& obj,
                         Mesh& mesh, bool two) {
  std::vector<int>& texcoords = mesh.property(obj.texcoord).data_vector();
  std::vector<int>& normals = mesh.property(obj.normal).data_vector();
  run_in_halves(two, mesh.n_faces(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const Triangle& corners = origins.face_corners[f];
      HalfedgeHandle h = mesh.halfedge_handle(FaceHandle(static_cast<int>(f)));
      for (int c = 0; c < 3; ++c, h = mesh.next_halfedge_handle(h)) {
        const auto k = static_cast<std::size_t>(corners[c]);
        const auto at = static_cast<std::size_t>(h.idx());
        if (!soup.corner_texcoord.empty()) texcoords[at] = soup.corner_texcoord[k];
        if (!soup.corner_normal.empty()) normals[at] = soup.corner_normal[k];
      }
    }
  });
}

// The per-face numbers some face of the soup has (the others get no property).
ObjFaceNumbers face_numbers_of(const Soup& soup) {
  return {!soup.face_material.empty(), !soup.face_group.empty(), !soup.face_object.empty(),
          !soup.face_smoothing.empty()};
}

// The soup's tables are moved to the mesh, which the soup is not read for again.
void copy_obj_values(Soup& soup, const SoupOrigins& origins, Mesh& mesh, bool two) {
  if (!has_obj_values(soup)) return;
  const ObjHandles obj = add_obj_handles(mesh, face_numbers_of(soup));
  if (has_corner_values(soup)) copy_corner_numbers(soup, origins, obj, mesh, two);
  const std::pair<const std::vector<int>*, OpenMesh::FPropHandleT<int>> per_face[] = {
      {&soup.face_material, obj.material},
      {&soup.face_group, obj.group},
      {&soup.face_object, obj.object},
      {&soup.face_smoothing, obj.smoothing}};
  for (const auto& [values, property] : per_face) {
    if (values->empty()) continue;
    copy_by_origin(*values, origins.face, mesh.property(property).data_vector(), two);
  }
  mesh.property(obj.tables) = std::move(soup.obj);
}

}  // namespace

void keep_file_format(const Soup& soup, Mesh& mesh) {
  const AttributeLayout plain;  // ASCII, double positions, uchar counts, int indices
  const AttributeLayout& file = soup.layout;
  if (file.encoding != plain.encoding || file.position_types != plain.position_types ||
      file.face_count_type != plain.face_count_type ||
      file.face_index_type != plain.face_index_type) {
    set_attribute_layout(mesh, file);
  }
}

bool has_corner_values(const Soup& soup) {
  return !soup.corner_texcoord.empty() || !soup.corner_normal.empty();
}

bool has_attributes(const Soup& soup) { return !soup.layout.empty() || has_obj_values(soup); }

void add_soup_properties(const Soup& soup, Mesh& mesh) {
  if (has_obj_values(soup)) add_obj_handles(mesh, face_numbers_of(soup));
}

void copy_soup_attributes(Soup& soup, const SoupOrigins& origins, Mesh& mesh, bool two) {
  copy_layout_values(soup, origins, mesh, two);
  copy_obj_values(soup, origins, mesh, two);
}

}  // namespace holefill::io
