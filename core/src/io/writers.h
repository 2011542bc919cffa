// The bytes of a mesh file: OBJ, OFF or PLY (ASCII), every coordinate as the shortest text that
// reads back to the same double (std::to_chars), so a round trip keeps every bit.
#pragma once

#include <string>

#include "holefill/mesh.h"

namespace holefill::io {

// The file for `mesh` in the format `ext` names (".obj", ".off" or ".ply"; anything else is
// written as PLY). Faces index live vertices only: the mesh must hold no deleted elements.
std::string mesh_file_bytes(const Mesh& mesh, const std::string& ext);

}  // namespace holefill::io
