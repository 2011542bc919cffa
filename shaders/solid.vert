#version 330 core
// Wireframe edges and patch vertices: positions only, pulled slightly toward the eye so that
// they win the depth test against the surface they lie on.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_depth_bias;  // world units toward the eye
uniform float u_point_size;        // pixels, at most
uniform float u_point_world_size;  // world units (0: u_point_size everywhere)
uniform float u_viewport_height;   // pixels

void main() {
  vec4 view_position = u_view * vec4(a_position, 1.0);
  view_position.xyz += normalize(-view_position.xyz) * u_depth_bias;
  gl_Position = u_projection * view_position;
  // A dot spans u_point_world_size on screen, so that dots on a dense patch stay apart.
  float pixels = u_point_world_size * u_projection[1][1] * 0.5 * u_viewport_height / gl_Position.w;
  gl_PointSize = u_point_world_size > 0.0 ? clamp(pixels, 2.0, u_point_size) : u_point_size;
}
