// OBJ: mtllib (its files named relative to the output's folder), vertices with their colours,
// the texture coordinates and normals (every one the file had, in its order, then those of
// patches that faces use), and the faces grouped by object and group in the order these first
// appear, with o, g, usemtl and s wherever they change (a file without s gets none).
#include <algorithm>
#include <array>
#include <filesystem>

#include "holefill/attributes.h"
#include "holefill/obj_attributes.h"
#include "text_out.h"
#include "writers.h"

namespace holefill::io {
namespace fs = std::filesystem;
namespace {

// The output's folder as a reader of the file will see it (links resolved).
fs::path output_folder(const fs::path& output) {
  std::error_code error;
  fs::path absolute = fs::absolute(output, error);
  fs::path resolved = fs::weakly_canonical(absolute, error);
  return (error ? absolute.lexically_normal() : resolved).parent_path();
}

void append_material_libraries(std::string& out, const ObjTables& tables, const fs::path& output) {
  std::string names;
  for (const auto& library : tables.material_libraries) {
    const fs::path name = material_library_name(library, output);
    if (!name.empty()) names += ' ' + name.generic_string();
  }
  if (!names.empty()) out += "mtllib" + names + '\n';
}

// Vertex colours as "v x y z r g b" (in [0, 1]: integer channels are scaled, others written as
// they are, so OBJ colours round-trip exactly).
void append_coloured_vertices(const Mesh& mesh, PieceOut& out) {
  const AttributeLayout layout = attribute_layout(mesh);
  std::vector<std::pair<OpenMesh::VPropHandleT<double>, double>> channels;  // and their scale
  for (const char* name : {"red", "green", "blue"}) {
    const auto found = std::find_if(layout.vertex.begin(), layout.vertex.end(),
                                    [&](const ScalarAttribute& a) { return a.name == name; });
    if (found == layout.vertex.end()) break;
    channels.emplace_back(vertex_attribute(mesh, name), full_intensity(found->type));
  }
  if (channels.size() != 3) channels.clear();
  out.records(mesh.n_vertices(), [&](std::string& text, std::size_t first, std::size_t last) {
    append_vertices(mesh, text, first, last, "v ", [&](VertexHandle v) {
      for (const auto& [property, scale] : channels) {
        text += ' ';
        append_number(
            text, scale == 1.0 ? mesh.property(property, v) : mesh.property(property, v) / scale);
      }
    });
  });
}

// The number each table entry is written as (indexed by the mesh's number, 0: not written):
// the file's entries all, the others when a face uses them.
std::vector<int> written_numbers(const Mesh& mesh, OpenMesh::HPropHandleT<int> property,
                                 std::size_t size, std::size_t from_file) {
  std::vector<char> used(size + 1, 0);
  std::fill(used.begin() + 1, used.begin() + 1 + static_cast<std::ptrdiff_t>(from_file), 1);
  for (const auto f : mesh.faces()) {
    for (const auto h : mesh.fh_range(f)) used[mesh.property(property, h)] = 1;
  }
  std::vector<int> number(size + 1, 0);
  int next = 0;
  for (std::size_t i = 1; i <= size; ++i) number[i] = used[i] ? ++next : 0;
  return number;
}

// One line per written entry of `values` (append(line, value) makes it).
template <class Values, class Append>
void append_table(const Values& values, const std::vector<int>& number, PieceOut& out,
                  Append&& append) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!number[i + 1]) continue;
    append(out.text, values[i]);
    out.end_record();
  }
}

void append_tables(PieceOut& out, const ObjTables& tables, const std::vector<int>& texcoord,
                   const std::vector<int>& normal) {
  append_table(tables.texcoords, texcoord, out,
               [&](std::string& line, const std::array<double, 3>& uvw) {
                 line += "vt";
                 for (int i = 0; i < tables.texcoord_size; ++i) {
                   line += ' ';
                   append_number(line, uvw[i]);
                 }
                 line += '\n';
               });
  append_table(tables.normals, normal, out, [&](std::string& line, const Point& n) {
    line += "vn";
    for (int axis = 0; axis < 3; ++axis) {
      line += ' ';
      append_number(line, n[axis]);
    }
    line += '\n';
  });
}

// The faces grouped by object, then group, in the order these first appear (stable: a file
// written grouped keeps its order, and a patch's faces join their group).
std::vector<FaceHandle> grouped_faces(const Mesh& mesh, const ObjHandles& obj,
                                      const ObjTables& tables) {
  std::vector<FaceHandle> faces(mesh.faces().begin(), mesh.faces().end());
  std::vector<int> object_rank(tables.objects.size() + 1, -1);
  std::vector<int> group_rank(tables.groups.size() + 1, -1);
  int objects = 0, groups = 0;
  for (const auto f : faces) {
    int& object = object_rank[obj_face_number(mesh, obj.object, f)];
    if (object < 0) object = objects++;
    int& group = group_rank[obj_face_number(mesh, obj.group, f)];
    if (group < 0) group = groups++;
  }
  auto key = [&](FaceHandle f) {
    return std::pair(object_rank[obj_face_number(mesh, obj.object, f)],
                     group_rank[obj_face_number(mesh, obj.group, f)]);
  };
  std::stable_sort(faces.begin(), faces.end(),
                   [&](FaceHandle a, FaceHandle b) { return key(a) < key(b); });
  return faces;
}

// "f v/vt/vn ...", with vt and vn where all the face's corners have one.
void append_face(const Mesh& mesh, FaceHandle f, const ObjHandles& obj,
                 const std::vector<int>& texcoord, const std::vector<int>& normal,
                 std::string& out) {
  bool has_texcoords = true, has_normals = true;
  for (const auto h : mesh.fh_range(f)) {
    has_texcoords = has_texcoords && texcoord[mesh.property(obj.texcoord, h)] != 0;
    has_normals = has_normals && normal[mesh.property(obj.normal, h)] != 0;
  }
  out += 'f';
  for (const auto h : mesh.fh_range(f)) {
    out += ' ';
    append_number(out, static_cast<long long>(mesh.to_vertex_handle(h).idx()) + 1);
    if (!has_texcoords && !has_normals) continue;
    out += '/';
    if (has_texcoords)
      append_number(out, static_cast<long long>(texcoord[mesh.property(obj.texcoord, h)]));
    if (has_normals) {
      out += '/';
      append_number(out, static_cast<long long>(normal[mesh.property(obj.normal, h)]));
    }
  }
  out += '\n';
}

// The faces in their groups' order, each block of them starting from the object, group,
// material and smoothing group of the face before it (none before the first), so that a block
// says what changes where the whole file would.
void append_faces_with_states(const Mesh& mesh, const ObjHandles& obj, const ObjTables& tables,
                              const std::vector<int>& texcoord, const std::vector<int>& normal,
                              PieceOut& pieces) {
  const std::vector<FaceHandle> faces = grouped_faces(mesh, obj, tables);
  pieces.records(faces.size(), [&](std::string& out, std::size_t first, std::size_t last) {
    // Writes "<keyword> <name>" when a face's number differs from the current one.
    auto switch_to = [&out](int& current, int number, const char* keyword,
                            const std::vector<std::string>& names, const char* none) {
      if (number == current) return;
      current = number;
      out += keyword;
      out += ' ';
      out += number ? names[number - 1] : none;
      out += '\n';
    };
    auto number = [&](OpenMesh::FPropHandleT<int> property, std::size_t i) {
      return i == 0 ? 0 : obj_face_number(mesh, property, faces[i - 1]);
    };
    int object = number(obj.object, first), group = number(obj.group, first),
        material = number(obj.material, first), smoothing = number(obj.smoothing, first);
    for (std::size_t i = first; i < last; ++i) {
      const FaceHandle f = faces[i];
      switch_to(object, obj_face_number(mesh, obj.object, f), "o", tables.objects, "");
      switch_to(group, obj_face_number(mesh, obj.group, f), "g", tables.groups, "default");
      switch_to(material, obj_face_number(mesh, obj.material, f), "usemtl", tables.materials, "");
      switch_to(smoothing, obj_face_number(mesh, obj.smoothing, f), "s", tables.smoothing_groups,
                "off");
      append_face(mesh, f, obj, texcoord, normal, out);
    }
  });
}

}  // namespace

fs::path material_library_name(const fs::path& library, const fs::path& output) {
  const fs::path relative = library.lexically_relative(output_folder(output));
  const std::string name = (relative.empty() ? library : relative).generic_string();
  const bool has_blank = std::any_of(name.begin(), name.end(), [](unsigned char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r' || c == '\n';
  });
  return has_blank ? fs::path() : fs::path(name);
}

void write_obj(const Mesh& mesh, const fs::path& output, PieceOut& out) {
  out.text += "# written by holefill\n";
  const ObjHandles obj = obj_handles(mesh);
  if (obj.valid()) append_material_libraries(out.text, mesh.property(obj.tables), output);
  append_coloured_vertices(mesh, out);
  if (!obj.valid()) {
    out.records(mesh.n_faces(), [&](std::string& text, std::size_t first, std::size_t last) {
      append_faces(mesh, text, first, last, "f ", 1, [](FaceHandle) {});
    });
    return;
  }
  const ObjTables& tables = mesh.property(obj.tables);
  const std::vector<int> texcoord =
      written_numbers(mesh, obj.texcoord, tables.texcoords.size(), tables.file_texcoords);
  const std::vector<int> normal =
      written_numbers(mesh, obj.normal, tables.normals.size(), tables.file_normals);
  append_tables(out, tables, texcoord, normal);
  append_faces_with_states(mesh, obj, tables, texcoord, normal, out);
}

}  // namespace holefill::io
