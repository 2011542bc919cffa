#version 330 core
// Wireframe edges and patch vertices: positions only, pulled slightly toward the eye so that
// they win the depth test against the surface they lie on.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_depth_bias;  // world units toward the eye
uniform float u_point_size;

void main() {
  vec4 view_position = u_view * vec4(a_position, 1.0);
  view_position.xyz += normalize(-view_position.xyz) * u_depth_bias;
  gl_Position = u_projection * view_position;
  gl_PointSize = u_point_size;
}
