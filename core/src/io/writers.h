// The bytes of a mesh file: OBJ, OFF, PLY or binary STL. Text numbers are the shortest text that
// reads back to the same value (std::to_chars), so a round trip keeps every bit. PLY is written
// in the encoding and types the mesh was read with (attributes.h's layout: float stays float)
// with every attribute; OFF with its colours and normals (COFF, NOFF); OBJ with vertex colours,
// texture coordinates, normals, materials, groups, objects and smoothing groups (obj_attributes.h).
#pragma once

#include <filesystem>
#include <string>

#include "holefill/mesh.h"
#include "holefill/mesh_format.h"
#include "holefill/output_file.h"

namespace holefill::io {

// Hands `write` the file for `mesh` in `format`, to be written at `output` (an OBJ names its
// material libraries relative to its folder), in pieces of about a megabyte. Faces index live
// vertices only: the mesh must hold no deleted elements. The records are formatted in blocks on
// `threads` threads (PieceOut), the same bytes on any number.
void write_mesh_file(const Mesh& mesh, MeshFormat format, const std::filesystem::path& output,
                     const ByteWriter& write, unsigned threads = 1);

// How an OBJ written at `output` names the material library `library`: relative to the output's
// folder (links resolved; the library's absolute path where there is no relative one). Empty when
// that name holds whitespace, which OBJ readers (tinyobjloader too) take as the gap between two
// libraries: such a library is not written, and attributes_not_written names it.
std::filesystem::path material_library_name(const std::filesystem::path& library,
                                            const std::filesystem::path& output);

class PieceOut;
// The OBJ file (obj_writer.cpp), handed on through `out` as it is made.
void write_obj(const Mesh& mesh, const std::filesystem::path& output, PieceOut& out);

}  // namespace holefill::io
