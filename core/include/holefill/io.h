// Reading and writing meshes. OBJ goes through tinyobjloader (positions welded by index,
// polygons triangulated); OFF, PLY and STL through OpenMesh's readers. Every failure throws a
// FileError naming the file and the reason; writes are atomic (temporary file, then rename).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "holefill/mesh.h"

namespace holefill {

// What loading had to change or noticed, for the user to read.
struct LoadReport {
  std::size_t polygons_triangulated = 0;     // faces with more than 3 corners
  std::size_t degenerate_faces_dropped = 0;  // faces using a vertex twice
  std::size_t faces_detached = 0;  // faces that would make an edge non-manifold, given own vertices
  std::vector<std::string> warnings;
};

// Loads a triangle mesh; the format is chosen by the file extension (obj, off, ply, stl).
Mesh load_mesh(const std::filesystem::path& path, LoadReport* report = nullptr);

// Writes OBJ, OFF or PLY (by extension) with full double precision. Either the whole file
// appears at `path` or nothing changes there.
void save_mesh(const Mesh& mesh, const std::filesystem::path& path);

// The file extensions load_mesh and save_mesh accept, lower case with the dot.
const std::vector<std::string>& readable_extensions();
const std::vector<std::string>& writable_extensions();

}  // namespace holefill
