// A linked GLSL program built from two embedded shaders, with uniform setters by name.
#pragma once

#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <string_view>

namespace holefill::viewer {

class GlProgram {
 public:
  // Compiles shaders/<vertex> and shaders/<fragment>; throws std::runtime_error with the log.
  GlProgram(std::string_view vertex, std::string_view fragment);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const { glUseProgram(id_); }
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat4& value) const;
  void set(const char* name, const glm::vec3* values, int count) const;
  void set(const char* name, const int* values, int count) const;

 private:
  GLuint id_ = 0;
};

}  // namespace holefill::viewer
