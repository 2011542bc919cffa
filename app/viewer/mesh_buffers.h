// GPU copies of one mesh (SurfaceArrays) and of its boundary loops. Uploaded once per mesh
// change; drawing is then one call per layer, which keeps million-triangle meshes interactive.
#pragma once

#include <epoxy/gl.h>

#include <vector>

#include "scene_arrays.h"

namespace holefill::viewer {

class MeshBuffers {
 public:
  MeshBuffers();
  ~MeshBuffers();
  MeshBuffers(const MeshBuffers&) = delete;
  MeshBuffers& operator=(const MeshBuffers&) = delete;

  void upload(const SurfaceArrays& arrays);
  // Binds the face-stage texture buffer to `texture_unit` and draws the triangles.
  void draw_surface(int texture_unit) const;
  void draw_edges() const;
  void draw_patch_vertices() const;

 private:
  GLuint vao_ = 0, positions_ = 0, normals_ = 0, triangles_ = 0;
  GLuint edges_vao_ = 0, edges_ = 0, edge_lengths_ = 0;
  GLuint points_vao_ = 0, points_ = 0;
  GLuint stages_ = 0, stages_texture_ = 0;
  GLuint colors_ = 0;
  bool has_colors_ = false;
  GLsizei triangle_indices_ = 0, edge_indices_ = 0, point_indices_ = 0;
};

class BoundaryBuffers {
 public:
  BoundaryBuffers();
  ~BoundaryBuffers();
  BoundaryBuffers(const BoundaryBuffers&) = delete;
  BoundaryBuffers& operator=(const BoundaryBuffers&) = delete;

  void upload(const std::vector<BoundarySegment>& segments);
  void draw() const;

 private:
  GLuint vao_ = 0, vertices_ = 0;
  GLsizei count_ = 0;
};

}  // namespace holefill::viewer
