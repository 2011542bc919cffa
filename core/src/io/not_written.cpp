// What a file format cannot hold of what the mesh carries (io.h: attributes_not_written), so that
// saving says what it leaves out instead of dropping it silently.
#include <algorithm>
#include <array>
#include <optional>
#include <utility>

#include "holefill/attributes.h"
#include "holefill/io.h"
#include "holefill/obj_attributes.h"
#include "writers.h"

namespace holefill {
namespace {

bool is_colour(const std::string& name) {
  return name == "red" || name == "green" || name == "blue" || name == "alpha";
}

bool is_normal(const std::string& name) { return name == "nx" || name == "ny" || name == "nz"; }

// Whether a file of `format` holds the vertex attribute `name`.
bool holds_vertex_attribute(std::optional<MeshFormat> format, const std::string& name) {
  if (!format) return false;
  switch (*format) {
    case MeshFormat::Ply:
      return true;
    case MeshFormat::Off:
      return is_colour(name) || is_normal(name);
    case MeshFormat::Obj:
      return is_colour(name) && name != "alpha";
    case MeshFormat::Stl:
      return false;
  }
  return false;
}

// Whether a file of `format` holds the mesh's face attributes; `only_colours` when they are all
// colours.
bool holds_face_attributes(std::optional<MeshFormat> format, bool only_colours) {
  if (!format) return false;
  switch (*format) {
    case MeshFormat::Ply:
      return true;
    case MeshFormat::Off:
      return only_colours;
    case MeshFormat::Obj:
    case MeshFormat::Stl:
      return false;
  }
  return false;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// What the OBJ tables hold ("texture coordinates, smoothing groups"); empty when nothing.
std::string obj_values_held(const Mesh& mesh) {
  const ObjHandles obj = obj_handles(mesh);
  if (!obj.valid()) return {};
  const ObjTables& tables = mesh.property(obj.tables);
  const std::pair<bool, const char*> kinds[] = {
      {!tables.texcoords.empty(), "texture coordinates"},
      {!tables.normals.empty(), "corner normals"},
      {!tables.materials.empty() || !tables.material_libraries.empty(), "materials"},
      {!tables.groups.empty(), "groups"},
      {!tables.objects.empty(), "objects"},
      {!tables.smoothing_groups.empty(), "smoothing groups"}};
  std::vector<std::string> held;
  for (const auto& [holds, name] : kinds) {
    if (holds) held.emplace_back(name);
  }
  return joined(held);
}

// The material libraries an OBJ written at `name` cannot name (material_library_name), each
// with the path it would have: a phrase, or empty when there is none.
std::string unnamed_material_libraries(const Mesh& mesh, const std::filesystem::path& name) {
  const ObjHandles obj = obj_handles(mesh);
  if (!obj.valid()) return {};
  std::vector<std::string> unnamed;
  for (const auto& library : mesh.property(obj.tables).material_libraries) {
    if (io::material_library_name(library, name).empty()) {
      std::string& quoted = unnamed.emplace_back(1, '\'');
      quoted += library.generic_string();
      quoted += '\'';
    }
  }
  if (unnamed.empty()) return {};
  return std::string(unnamed.size() == 1 ? "the material library " : "the material libraries ") +
         joined(unnamed) +
         " (the path from the output's folder holds a space, which OBJ readers take as the "
         "gap between two libraries)";
}

// What a file of `format` (none: an extension that names no format) leaves out.
std::vector<std::string> not_written(const Mesh& mesh, std::optional<MeshFormat> format,
                                     const std::filesystem::path& name) {
  const AttributeLayout layout = attribute_layout(mesh);
  const bool off_faces = std::all_of(layout.face.begin(), layout.face.end(),
                                     [](const ScalarAttribute& a) { return is_colour(a.name); });
  std::vector<std::string> vertex, face;
  for (const auto& a : layout.vertex) {
    if (!holds_vertex_attribute(format, a.name)) vertex.push_back(a.name);
  }
  if (!holds_face_attributes(format, off_faces)) {
    for (const auto& a : layout.face) face.push_back(a.name);
  }
  std::vector<std::string> lost;
  if (!vertex.empty()) lost.push_back("vertex properties " + joined(vertex));
  if (!face.empty()) lost.push_back("face properties " + joined(face));
  const bool obj = format == MeshFormat::Obj;
  const std::string obj_values = obj ? std::string() : obj_values_held(mesh);
  if (!obj_values.empty()) lost.push_back(obj_values + " (only OBJ holds them)");
  const std::string libraries = obj ? unnamed_material_libraries(mesh, name) : "";
  if (!libraries.empty()) lost.push_back(libraries);
  return lost;
}

}  // namespace

std::vector<std::string> attributes_not_written(const Mesh& mesh,
                                                const std::filesystem::path& name) {
  return not_written(mesh, format_from_path(name), name);
}

std::vector<std::string> attributes_not_written(const Mesh& mesh, MeshFormat format,
                                                const std::filesystem::path& name) {
  return not_written(mesh, format, name);
}

}  // namespace holefill
