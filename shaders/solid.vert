#version 330 core
// Wireframe edges and patch vertices: positions, pulled slightly toward the eye so that they
// win the depth test against the surface they lie on. Wireframe lines fade where they crowd:
// a vertex's mean edge length, in pixels at its depth, says how far apart lines run there;
// below a few pixels they would merge into moiré, so they fade out instead. Patch vertices fade
// the same way by the patch's edge length on screen (three dot widths): a dense patch seen
// whole shows a faint red haze, not a red blot, and each dot comes back as the view zooms in.
layout(location = 0) in vec3 a_position;
layout(location = 1) in float a_edge_length;  // world units (edges only)

uniform mat4 u_view;
uniform mat4 u_projection;
uniform float u_depth_bias;  // world units toward the eye
uniform float u_point_size;        // pixels, at most
uniform float u_point_world_size;  // world units (0: u_point_size everywhere)
uniform float u_viewport_height;   // pixels
uniform bool u_fade;               // edges: fade by a_edge_length
uniform float u_pixel_size;        // the world length of a pixel at depth 1
uniform vec2 u_fade_pixels;        // invisible at x pixels apart, full at y (edges and dots)

out float v_alpha;

void main() {
  vec4 view_position = u_view * vec4(a_position, 1.0);
  view_position.xyz += normalize(-view_position.xyz) * u_depth_bias;
  gl_Position = u_projection * view_position;
  float apart = a_edge_length / (u_pixel_size * max(-view_position.z, 1e-6));
  // A dot spans u_point_world_size on screen, so that dots on a dense patch stay apart.
  float pixels = u_point_world_size * u_projection[1][1] * 0.5 * u_viewport_height / gl_Position.w;
  gl_PointSize = u_point_world_size > 0.0 ? clamp(pixels, 2.0, u_point_size) : u_point_size;
  if (u_fade)
    v_alpha = smoothstep(u_fade_pixels.x, u_fade_pixels.y, apart);
  else if (u_point_world_size > 0.0)
    v_alpha = smoothstep(u_fade_pixels.x, u_fade_pixels.y, 3.0 * pixels);
  else
    v_alpha = 1.0;
}
