// What a file carries beyond positions and faces (PLY properties of any type, OFF and OBJ vertex
// colours and normals), kept on the mesh as OpenMesh properties so that every stage carries them
// without knowing them, and written back by save_mesh. Property names (for code that copies or
// re-adds elements, e.g. with copy_all_properties):
//   "holefill:attributes"  mesh property, AttributeLayout: which attributes, their order and types
//   "holefill:v:NAME"      VPropHandleT<double>, one per vertex attribute NAME (red, nx, quality..)
//   "holefill:f:NAME"      FPropHandleT<double>, one per face attribute NAME
// Values are held as doubles: every PLY type converts to double and back exactly, so original
// elements keep their values bit for bit.
// After a hole is filled, interpolate_patch_attributes gives the new elements values (the
// pipeline calls it after every stage).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill {

// The types of PLY's properties (OFF and OBJ attributes are Float64, or UInt8 for 0-255 colours).
enum class ScalarType : std::uint8_t {
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

struct ScalarAttribute {
  std::string name;
  ScalarType type = ScalarType::Float64;
};

enum class FileEncoding : std::uint8_t { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct AttributeLayout {
  std::vector<ScalarAttribute> vertex;  // in the file's order (positions excluded)
  std::vector<ScalarAttribute> face;    // scalar face properties, in the file's order
  // How the source PLY stored positions and faces, so that a PLY is written back alike.
  std::array<ScalarType, 3> position_types{ScalarType::Float64, ScalarType::Float64,
                                           ScalarType::Float64};  // x, y, z
  ScalarType face_count_type = ScalarType::UInt8;
  ScalarType face_index_type = ScalarType::Int32;
  FileEncoding encoding = FileEncoding::Ascii;
  bool empty() const { return vertex.empty() && face.empty(); }
};

// The layout the mesh carries (an empty one when it carries none).
AttributeLayout attribute_layout(const Mesh& mesh);

// Records `layout` on the mesh and adds the properties it names (where missing, valued 0).
void set_attribute_layout(Mesh& mesh, const AttributeLayout& layout);

// The property of a vertex or face attribute; invalid when the mesh has none of that name.
OpenMesh::VPropHandleT<double> vertex_attribute(const Mesh& mesh, const std::string& name);
OpenMesh::FPropHandleT<double> face_attribute(const Mesh& mesh, const std::string& name);
// The properties of `attributes` (a layout's vertex or face list), in its order, found in one pass
// over the mesh's properties (invalid where missing): a lookup by name passes over them all.
std::vector<OpenMesh::VPropHandleT<double>> vertex_attributes(
    const Mesh& mesh, const std::vector<ScalarAttribute>& attributes);
std::vector<OpenMesh::FPropHandleT<double>> face_attributes(
    const Mesh& mesh, const std::vector<ScalarAttribute>& attributes);

// Values for the patch's new vertices and its faces: scalar vertex attributes (colours, quality,
// ...) are interpolated harmonically (umbrella weights) from the hole's boundary, normals
// (nx, ny, nz) are the new geometry's, and face attributes take the value most faces along the
// hole have; then OBJ's corners and faces (interpolate_patch_obj_attributes). Original elements
// are not touched. Returns a note saying what could not be given to the patch (empty when
// nothing), e.g. texture coordinates across a UV seam.
std::string interpolate_patch_attributes(Mesh& mesh, const Patch& patch);

// The value of a colour channel at full intensity: the largest value of an integer type (255 for
// uchar), 1 for floating-point types.
double full_intensity(ScalarType type);

// Per-vertex colours in [0, 1] when the mesh carries red, green and blue (integer types scaled
// by their range, e.g. uchar by 255); false, with `rgb` cleared, otherwise.
bool vertex_colors(const Mesh& mesh, std::vector<std::array<float, 3>>& rgb);

}  // namespace holefill
