#include "gl_program.h"

#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string>

#include "shader_sources.h"

namespace holefill::viewer {
namespace {

GLuint compile(GLenum type, std::string_view name) {
  const std::string_view source = shader_source(name);
  const GLchar* text = source.data();
  const GLint length = static_cast<GLint>(source.size());
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error("shader " + std::string(name) + " does not compile:\n" + log);
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(std::string_view vertex, std::string_view fragment) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment);
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(id_, sizeof log, nullptr, log);
    glDeleteProgram(id_);
    throw std::runtime_error("shaders " + std::string(vertex) + " + " + std::string(fragment) +
                             " do not link:\n" + log);
  }
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

void GlProgram::set(const char* name, int value) const {
  glUniform1i(glGetUniformLocation(id_, name), value);
}
void GlProgram::set(const char* name, float value) const {
  glUniform1f(glGetUniformLocation(id_, name), value);
}
void GlProgram::set(const char* name, const glm::vec2& value) const {
  glUniform2fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(value));
}
void GlProgram::set(const char* name, const glm::vec4& value) const {
  glUniform4fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(value));
}
void GlProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(glGetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(value));
}
void GlProgram::set(const char* name, const glm::vec3* values, int count) const {
  glUniform3fv(glGetUniformLocation(id_, name), count, glm::value_ptr(values[0]));
}

void GlProgram::set(const char* name, const int* values, int count) const {
  glUniform1iv(glGetUniformLocation(id_, name), count, values);
}

}  // namespace holefill::viewer
