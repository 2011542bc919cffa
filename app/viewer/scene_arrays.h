// What the renderer uploads, computed from a mesh and its patches without any GL: flat arrays
// of positions, normals, triangles with the stage that created each, edges, patch vertices, and
// the unfilled holes' boundary segments.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "holefill/fill.h"

namespace holefill::viewer {

struct SurfaceArrays {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;         // area-weighted vertex normals
  std::vector<glm::vec4> colors;          // the file's vertex colours (alpha 1), or empty
  std::vector<std::uint32_t> triangles;   // 3 per face, in face order
  std::vector<std::uint8_t> face_stages;  // Stage per face (Original outside patches)
  std::vector<std::uint32_t> edges;       // 2 per edge, for the wireframe
  // Per vertex, the mean length of its edges (0 for an isolated vertex): how far apart the
  // wireframe's lines run there, which the shader turns into pixels to fade it where dense.
  std::vector<float> vertex_edge_lengths;
  std::vector<std::uint32_t> patch_vertices;  // vertices the patches added
  float patch_edge_length = 0.0f;             // mean length of their edges (0: none), for dot sizes
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};
};

// `fills` are the patches on this mesh (their faces get stage colours: the stage that made each
// face, Smoothed for all of a smoothed patch's; their vertices dots).
SurfaceArrays surface_arrays(const Mesh& mesh, const std::vector<const HoleFill*>& fills);

struct BoundarySegment {
  glm::vec3 a{0.0f};
  glm::vec3 b{0.0f};
  int hole_id = -1;
};

// The boundary segments of every hole in `holes` that is not yet filled on `mesh`.
std::vector<BoundarySegment> boundary_segments(const Mesh& mesh, const std::vector<Hole>& holes);

// The hole's boundary points, world coordinates (for picking and framing).
std::vector<glm::vec3> boundary_points(const Mesh& mesh, const Hole& hole);

// A direction to look at the hole from: the mean normal of the faces around it, pointing out of
// the surface (toward where the patch faces).
glm::vec3 hole_view_direction(const Mesh& mesh, const Hole& hole);

}  // namespace holefill::viewer
