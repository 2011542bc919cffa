// Reading and writing meshes. OFF, PLY (ASCII and binary) and STL (ASCII and binary) are read by
// our own parsers, OBJ through tinyobjloader with its numbers read again exactly, in double
// precision, into a list of polygons that is then checked and
// repaired before it becomes a mesh: polygons are triangulated, faces flipped to agree with
// their neighbours, exact duplicates and faces using a vertex twice dropped, faces that would make
// an edge non-manifold kept on their own copies of their corners, and a vertex where closed
// surfaces touch split into one copy per surface. Every repair is
// counted in a LoadReport; every refusal throws a FileError naming the file and the reason.
// Text may start with a UTF-8 byte-order mark and end its lines with LF, CR LF or CR. Data after
// what an OFF or PLY header counts (or a binary STL's triangle count) is ignored with a warning
// rather than refused: the header is what the exporter meant, and trailing bytes are a common
// exporter habit (padding, signatures); the warning tells a user whose counts are wrong.
// load_mesh refuses what a file's first 64 KiB rule out before reading the rest.
// Writes are atomic (output_file.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/mesh_format.h"
#include "holefill/output_file.h"

namespace holefill {

// What loading had to change or noticed, for the user to read.
struct LoadReport {
  std::size_t polygons_triangulated = 0;     // faces with more than 3 corners
  std::size_t degenerate_faces_dropped = 0;  // faces using a vertex twice, or with < 3 corners
  std::size_t faces_detached = 0;  // faces that would make an edge non-manifold, given own vertices
  std::size_t vertices_split = 0;  // where closed surfaces touch: one copy per surface
  std::size_t faces_flipped = 0;   // turned over to agree with the orientation of their neighbours
  std::size_t duplicate_faces_dropped = 0;  // the same corners in the same order as a kept face
  std::size_t duplicate_positions = 0;      // vertices at exactly the position of an earlier vertex
  std::size_t isolated_vertices = 0;        // vertices no face uses (kept)
  std::size_t elements_ignored = 0;         // OBJ lines, points and curves: not surfaces
  std::string format;                       // what the contents were read as: obj, off, ply or stl
  std::vector<std::string> warnings;        // one sentence per kind of repair or oddity
};

// Loads a triangle mesh with the attributes its file carries (attributes.h): PLY's vertex and
// face properties, OFF's colours and normals, OBJ's vertex colours, per-corner texture
// coordinates and normals, materials, groups, smoothing groups and material libraries
// (obj_attributes.h); what cannot be kept (other PLY elements and lists, OBJ's free-form
// statements) is named in a warning. The format is chosen by the file's contents where they are
// unmistakable (a PLY or OFF header, a binary STL's size) and by its extension otherwise; a file
// whose extension says otherwise is read by its contents, with a warning. The format is decided
// once, from the first 64 KiB of a bigger file (unless its first keyword line runs past them). A
// big mesh is read and assembled on up to `threads` threads (0: every core this process may run
// on); the mesh, the report and every message are the same whatever the number.
Mesh load_mesh(const std::filesystem::path& path, LoadReport* report = nullptr,
               unsigned threads = 0);

// Reads a mesh from bytes already in memory; `name` stands in for the path in errors and
// chooses the format like a file name's extension. load_mesh is this on the file's contents.
Mesh load_mesh_from_memory(const std::string& bytes, const std::filesystem::path& name,
                           LoadReport* report = nullptr, unsigned threads = 0);

// Writes OBJ, OFF, PLY or binary STL (by extension: format_from_path): numbers as the shortest text
// that reads back to the same value, PLY in the encoding and property types it was read with and
// with every attribute the mesh carries (attributes.h), OFF with its colours and normals, OBJ with
// vertex colours and what obj_attributes.h keeps (material libraries named relative to `path`'s
// folder); through write_output_file (output_file.h): either the whole file appears at `path` or
// nothing changes there, links are followed and permissions kept. Throws FileError saying why it
// could not be written (for an extension that names no format: before anything is written).
// The text or records of a big mesh are made on up to `threads` threads (0: every core this
// process may run on; 1 starts none): the same bytes on any number.
void save_mesh(const Mesh& mesh, const std::filesystem::path& path, unsigned threads = 0);
// The same in `format`, whatever `path`'s extension (for callers that decided it already).
void save_mesh(const Mesh& mesh, const std::filesystem::path& path, MeshFormat format,
               unsigned threads = 0);

// Hands `write` the bytes save_mesh writes for `mesh` in the format `name`'s extension says (.obj
// .off .ply .stl), in order, in pieces of about a megabyte as they are made, for callers that
// send them elsewhere (standard output): the file never exists whole in memory. Throws FileError
// naming `name` for another extension, before any piece; what `write` throws passes through.
void write_mesh_pieces(const Mesh& mesh, const std::filesystem::path& name, const ByteWriter& write,
                       unsigned threads = 0);
// The same in `format`; `name` stands in for the file in errors and names an OBJ's material
// libraries relative to its folder.
void write_mesh_pieces(const Mesh& mesh, MeshFormat format, const std::filesystem::path& name,
                       const ByteWriter& write, unsigned threads = 0);

// The bytes write_mesh_pieces hands on, whole.
std::string mesh_to_bytes(const Mesh& mesh, const std::filesystem::path& name,
                          unsigned threads = 0);

// What save_mesh leaves out of a file of `name`'s format (by extension) that the mesh carries,
// one phrase per kind (e.g. "vertex properties quality" for an OBJ, "texture coordinates, ..."
// for a PLY of an OBJ's mesh; for an OBJ, material libraries whose path from `name`'s folder holds
// a space); empty when the file holds everything. For callers to warn.
std::vector<std::string> attributes_not_written(const Mesh& mesh,
                                                const std::filesystem::path& name);
// The same for a file of `format` written at `name`.
std::vector<std::string> attributes_not_written(const Mesh& mesh, MeshFormat format,
                                                const std::filesystem::path& name);

// The file extensions load_mesh and save_mesh accept, lower case with the dot (kMeshFormats').
const std::vector<std::string>& readable_extensions();
const std::vector<std::string>& writable_extensions();

}  // namespace holefill
