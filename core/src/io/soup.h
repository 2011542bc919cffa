// The polygons a file describes, as read and before any check of the mesh they make: what every
// reader returns and the repairs (soup_to_mesh) turn into a Mesh.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "face_lines.h"
#include "holefill/attributes.h"
#include "holefill/errors.h"
#include "holefill/mesh.h"
#include "holefill/obj_attributes.h"

namespace holefill::io {

// Positions and faces as read, before any check of the mesh they make.
struct Soup {
  std::vector<Point> positions;
  std::vector<int> corners;           // vertex indices of all faces, one after another
  std::vector<std::size_t> face_end;  // face f uses corners [face_end[f-1], face_end[f])
  // Where each face was read, for messages (a binary file's faces: none known).
  FaceLines face_line;
  // What the file carried beyond positions and faces: one column per attribute of the layout,
  // with a value per position (vertex) or per face.
  AttributeLayout layout;
  std::vector<std::vector<double>> vertex_values;
  std::vector<std::vector<double>> face_values;
  // What an OBJ carries per corner and per face (obj_attributes.h): the tables, then per corner
  // (parallel to corners) the texture coordinate and normal numbers, per face the material,
  // group, object and smoothing group numbers (1-based into the tables, 0: none); each empty when
  // none is used.
  ObjTables obj;
  std::vector<int> corner_texcoord, corner_normal;
  std::vector<int> face_material, face_group, face_object, face_smoothing;
  std::size_t face_begin(std::size_t f) const { return f == 0 ? 0 : face_end[f - 1]; }
  std::size_t face_count() const { return face_end.size(); }
  // Closes the face whose last corner is corners[end - 1] (corners may be filled later).
  void end_face(std::size_t end, std::size_t line) {
    face_end.push_back(end);
    face_line.add(face_end.size() - 1, line);
  }
};

// Indices into the soup's positions are ints (as OpenMesh's handles are).
constexpr long long kMaxVertices = std::numeric_limits<int>::max() - 1;

// Throws InvalidMeshError naming the vertex (and its line when known) unless p is finite.
inline void require_finite(const Point& p, std::size_t vertex_number, std::size_t line,
                           const std::filesystem::path& path) {
  if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) return;
  throw InvalidMeshError(path, (line ? "line " + std::to_string(line) + ": " : std::string()) +
                                   "vertex " + std::to_string(vertex_number) +
                                   " has a non-finite (NaN or infinite) coordinate");
}

// Exact positions as hash keys (-0 and +0 are one position).
struct PositionKey {
  std::array<std::uint64_t, 3> bits;
  explicit PositionKey(const Point& p) {
    for (int axis = 0; axis < 3; ++axis) bits[axis] = std::bit_cast<std::uint64_t>(p[axis] + 0.0);
  }
  bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
  std::size_t operator()(const PositionKey& key) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const auto b : key.bits) h = (h ^ b) * 0x100000001B3ull + (h >> 29);
    return static_cast<std::size_t>(h);
  }
};

}  // namespace holefill::io
