// What an OBJ file carries beyond positions and vertex colours: a texture coordinate (vt) and a
// normal (vn) per face corner, each face's material (usemtl) and the libraries that define the
// materials (mtllib), each face's group (g), object (o) and smoothing group (s). Kept on the mesh
// as OpenMesh properties so that every stage carries them, and written back by save_mesh as OBJ:
//   "holefill:obj"           mesh property, ObjTables: the values and names the numbers below
//                            count into
//   "holefill:obj:texcoord"  HPropHandleT<int>, per halfedge h with a face: the corner of face(h)
//                            at to_vertex(h) uses texcoords[n - 1]; 0: no texture coordinate
//   "holefill:obj:normal"    HPropHandleT<int>, likewise into normals
//   "holefill:obj:material"  FPropHandleT<int>, materials[n - 1]; 0: none
//   "holefill:obj:group"     FPropHandleT<int>, groups[n - 1]; 0: none
//   "holefill:obj:object"    FPropHandleT<int>, objects[n - 1]; 0: none
//   "holefill:obj:smoothing" FPropHandleT<int>, smoothing_groups[n - 1]; 0: none (before any s
//                            statement: smoothing off)
// Numbers count from 1, as in the file, so that the 0 OpenMesh gives an element added later
// means "none". Original elements keep their numbers, so their values survive bit for bit.
// The four per-face numbers are properties only where some face has one (a loaded file without
// o statements has no object property: 4 MB a million faces); without the property every face
// has 0, which obj_face_number reads.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill {

struct ObjTables {
  std::vector<std::array<double, 3>> texcoords;  // u v w: the file's vt lines, then patches'
  int texcoord_size = 2;                         // numbers each vt line has (1 to 3) when written
  std::vector<Point> normals;                    // the file's vn lines, then patches'
  std::size_t file_texcoords = 0;  // the first ones came from the file: written even when unused
  std::size_t file_normals = 0;
  std::vector<std::string> materials;  // usemtl names
  std::vector<std::string> groups;     // g statements' names (several joined by a space)
  std::vector<std::string> objects;    // o names
  // s statements' values as written ("1", "off", "0", ...): the spelling and a first "s off"
  // survive a round trip.
  std::vector<std::string> smoothing_groups;
  // The material libraries (mtllib), as absolute paths: written relative to the output's folder.
  std::vector<std::filesystem::path> material_libraries;
};

struct ObjHandles {
  OpenMesh::MPropHandleT<ObjTables> tables;
  OpenMesh::HPropHandleT<int> texcoord, normal;
  OpenMesh::FPropHandleT<int> material, group, object, smoothing;  // each may be invalid (none)
  bool valid() const { return tables.is_valid(); }
};

// Which per-face numbers add_obj_handles gives a mesh.
struct ObjFaceNumbers {
  bool material = true, group = true, object = true, smoothing = true;
};

// The mesh's OBJ properties; invalid handles when it has none (and for each per-face number it
// has no property for).
ObjHandles obj_handles(const Mesh& mesh);

// The mesh's OBJ properties, added (empty tables, every number 0) where missing: the tables, the
// corner numbers and the per-face numbers `face_numbers` names (all by default).
ObjHandles add_obj_handles(Mesh& mesh, const ObjFaceNumbers& face_numbers = {});

// Face f's number in `property` (one of ObjHandles' per-face numbers): 0 when the mesh has no
// such property.
inline int obj_face_number(const Mesh& mesh, OpenMesh::FPropHandleT<int> property, FaceHandle f) {
  return property.is_valid() ? mesh.property(property, f) : 0;
}

// Values for the patch's faces and corners (interpolate_patch_attributes calls it): each face
// takes the material, group, object and smoothing group most original faces along the hole have;
// texture coordinates are interpolated harmonically from the boundary's when the boundary lies in
// one chart (each boundary vertex has one texture coordinate on all its original faces), otherwise
// the patch has none; corner normals are the new geometry's (the mean of the patch's face
// normals around the vertex), a boundary vertex whose original corners share one normal keeps it.
// Original elements are not touched. Returns a note for the user when something could not be
// carried (empty otherwise).
std::string interpolate_patch_obj_attributes(Mesh& mesh, const Patch& patch);

}  // namespace holefill
