#include "mesh_buffers.h"

#include <cstddef>

namespace holefill::viewer {
namespace {

template <class T>
void fill_buffer(GLenum target, GLuint buffer, const std::vector<T>& data) {
  glBindBuffer(target, buffer);
  glBufferData(target, static_cast<GLsizeiptr>(data.size() * sizeof(T)),
               data.empty() ? nullptr : data.data(), GL_STATIC_DRAW);
}

void vec3_attribute(GLuint location, GLuint buffer) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
}

// One corner of a boundary quad, as thick_line.vert reads it.
struct LineCorner {
  glm::vec3 start;
  glm::vec3 end;
  glm::vec2 corner;
  GLint hole;
};

}  // namespace

MeshBuffers::MeshBuffers() {
  glGenVertexArrays(1, &vao_);
  glGenVertexArrays(1, &edges_vao_);
  glGenVertexArrays(1, &points_vao_);
  GLuint buffers[8];
  glGenBuffers(8, buffers);
  positions_ = buffers[0];
  normals_ = buffers[1];
  triangles_ = buffers[2];
  edges_ = buffers[3];
  points_ = buffers[4];
  stages_ = buffers[5];
  colors_ = buffers[6];
  edge_lengths_ = buffers[7];
  glGenTextures(1, &stages_texture_);

  glBindVertexArray(vao_);
  vec3_attribute(0, positions_);
  vec3_attribute(1, normals_);
  glBindBuffer(GL_ARRAY_BUFFER, colors_);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangles_);
  glBindVertexArray(edges_vao_);
  vec3_attribute(0, positions_);
  glBindBuffer(GL_ARRAY_BUFFER, edge_lengths_);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, sizeof(float), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, edges_);
  glBindVertexArray(points_vao_);
  vec3_attribute(0, positions_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, points_);
  glBindVertexArray(0);
}

MeshBuffers::~MeshBuffers() {
  const GLuint buffers[] = {positions_, normals_, triangles_, edges_,
                            points_,    stages_,  colors_,    edge_lengths_};
  glDeleteBuffers(8, buffers);
  glDeleteTextures(1, &stages_texture_);
  const GLuint arrays[] = {vao_, edges_vao_, points_vao_};
  glDeleteVertexArrays(3, arrays);
}

void MeshBuffers::upload(const SurfaceArrays& arrays) {
  glBindVertexArray(0);
  fill_buffer(GL_ARRAY_BUFFER, positions_, arrays.positions);
  fill_buffer(GL_ARRAY_BUFFER, normals_, arrays.normals);
  fill_buffer(GL_ARRAY_BUFFER, colors_, arrays.colors);
  fill_buffer(GL_ARRAY_BUFFER, edge_lengths_, arrays.vertex_edge_lengths);
  glBindVertexArray(vao_);
  has_colors_ = !arrays.colors.empty();
  if (has_colors_) {
    glEnableVertexAttribArray(2);
  } else {
    glDisableVertexAttribArray(2);
  }
  fill_buffer(GL_ELEMENT_ARRAY_BUFFER, triangles_, arrays.triangles);
  glBindVertexArray(edges_vao_);
  fill_buffer(GL_ELEMENT_ARRAY_BUFFER, edges_, arrays.edges);
  glBindVertexArray(points_vao_);
  fill_buffer(GL_ELEMENT_ARRAY_BUFFER, points_, arrays.patch_vertices);
  glBindVertexArray(0);
  // A texture buffer may not be empty-sized on every driver; keep at least one entry.
  std::vector<std::uint8_t> stages = arrays.face_stages;
  if (stages.empty()) stages.push_back(0);
  fill_buffer(GL_TEXTURE_BUFFER, stages_, stages);
  glBindTexture(GL_TEXTURE_BUFFER, stages_texture_);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_R8UI, stages_);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  triangle_indices_ = static_cast<GLsizei>(arrays.triangles.size());
  edge_indices_ = static_cast<GLsizei>(arrays.edges.size());
  point_indices_ = static_cast<GLsizei>(arrays.patch_vertices.size());
}

void MeshBuffers::draw_surface(int texture_unit) const {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(texture_unit));
  glBindTexture(GL_TEXTURE_BUFFER, stages_texture_);
  glBindVertexArray(vao_);
  if (!has_colors_) glVertexAttrib4f(2, 0.0f, 0.0f, 0.0f, 0.0f);  // alpha 0: no file colour
  glDrawElements(GL_TRIANGLES, triangle_indices_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

void MeshBuffers::draw_edges() const {
  glBindVertexArray(edges_vao_);
  glDrawElements(GL_LINES, edge_indices_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

void MeshBuffers::draw_patch_vertices() const {
  if (point_indices_ == 0) return;
  glBindVertexArray(points_vao_);
  glDrawElements(GL_POINTS, point_indices_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

BoundaryBuffers::BoundaryBuffers() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vertices_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vertices_);
  const auto stride = static_cast<GLsizei>(sizeof(LineCorner));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(offsetof(LineCorner, start)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(offsetof(LineCorner, end)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(offsetof(LineCorner, corner)));
  glEnableVertexAttribArray(3);
  glVertexAttribIPointer(3, 1, GL_INT, stride,
                         reinterpret_cast<const void*>(offsetof(LineCorner, hole)));
  glBindVertexArray(0);
}

BoundaryBuffers::~BoundaryBuffers() {
  glDeleteBuffers(1, &vertices_);
  glDeleteVertexArrays(1, &vao_);
}

void BoundaryBuffers::upload(const std::vector<BoundarySegment>& segments) {
  static constexpr glm::vec2 kQuad[6] = {{0, -1}, {1, -1}, {1, 1}, {0, -1}, {1, 1}, {0, 1}};
  std::vector<LineCorner> corners;
  corners.reserve(6 * segments.size());
  for (const auto& segment : segments) {
    for (const auto& corner : kQuad)
      corners.push_back({segment.a, segment.b, corner, segment.hole_id});
  }
  fill_buffer(GL_ARRAY_BUFFER, vertices_, corners);
  count_ = static_cast<GLsizei>(corners.size());
}

void BoundaryBuffers::draw() const {
  if (count_ == 0) return;
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, count_);
  glBindVertexArray(0);
}

}  // namespace holefill::viewer
