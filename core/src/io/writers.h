// The bytes of a mesh file: OBJ, OFF, PLY or binary STL. Text numbers are the shortest text that
// reads back to the same value (std::to_chars), so a round trip keeps every bit. PLY is written
// in the encoding and types the mesh was read with (attributes.h's layout: float stays float)
// with every attribute; OFF with its colours and normals (COFF, NOFF); OBJ with vertex colours.
#pragma once

#include <string>

#include "holefill/mesh.h"

namespace holefill::io {

// The file for `mesh` in the format `ext` names (".obj", ".off", ".stl"; anything else is
// written as PLY). Faces index live vertices only: the mesh must hold no deleted elements.
std::string mesh_file_bytes(const Mesh& mesh, const std::string& ext);

}  // namespace holefill::io
