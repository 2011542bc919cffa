#version 330 core
// Boundary loops as thick lines: core profile has no wide lines, so each segment is a quad of
// two triangles expanded in screen space. Every vertex carries both segment ends and a corner:
// x = 0 or 1 (which end), y = -1 or +1 (which side).
layout(location = 0) in vec3 a_start;
layout(location = 1) in vec3 a_end;
layout(location = 2) in vec2 a_corner;
layout(location = 3) in int a_hole;

uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec2 u_viewport;     // pixels
uniform float u_width;       // pixels
uniform float u_depth_bias;  // world units toward the eye
// Pixels toward the eye, as world lengths at each point's depth (u_pixel_size: the world length
// of a pixel at depth 1): the quad reaches u_width / 2 pixels beside the loop, over surface that
// near a silhouette rises toward the eye far faster than the flat bias covers, and would cut the
// outline into dashes.
uniform float u_pixel_bias;
uniform float u_pixel_size;

flat out int v_hole;

vec4 project(vec3 position) {
  vec4 view_position = u_view * vec4(position, 1.0);
  float depth = -view_position.z;
  float bias = u_depth_bias + u_pixel_bias * u_pixel_size * depth;
  // Never to the eye's side of the near plane: at most half the way to the eye.
  view_position.xyz += normalize(-view_position.xyz) * min(bias, 0.5 * depth);
  return u_projection * view_position;
}

void main() {
  vec4 start = project(a_start);
  vec4 end = project(a_end);
  vec2 start_pixels = start.xy / start.w * 0.5 * u_viewport;
  vec2 end_pixels = end.xy / end.w * 0.5 * u_viewport;
  vec2 along = end_pixels - start_pixels;
  along = length(along) > 1e-4 ? normalize(along) : vec2(1.0, 0.0);
  vec2 across = vec2(-along.y, along.x);
  vec4 position = a_corner.x < 0.5 ? start : end;
  // Widen sideways, and lengthen by half the width so that neighbouring segments join.
  vec2 offset_pixels = (across * a_corner.y + along * (a_corner.x * 2.0 - 1.0)) * 0.5 * u_width;
  position.xy += offset_pixels / (0.5 * u_viewport) * position.w;
  gl_Position = position;
  v_hole = a_hole;
}
