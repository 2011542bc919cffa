#version 330 core
// The mesh surface: positions and smooth normals in view space for the fragment shader.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;  // the file's vertex colour; alpha 0 where it has none

uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_view_position;
out vec3 v_view_normal;
out vec4 v_color;

void main() {
  vec4 view_position = u_view * vec4(a_position, 1.0);
  v_view_position = view_position.xyz;
  v_view_normal = mat3(u_view) * a_normal;
  v_color = a_color;
  gl_Position = u_projection * view_position;
}
