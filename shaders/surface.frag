#version 330 core
// Headlight shading, flat (from screen-space derivatives) or smooth (interpolated normals).
// Each face takes the colour of the stage that created it, read from a texture buffer indexed
// by gl_PrimitiveID (one entry per triangle, in draw order). Back faces are tinted so that the
// inside of the surface, seen through a hole, reads as inside.
in vec3 v_view_position;
in vec3 v_view_normal;
in vec4 v_color;

uniform bool u_flat;
uniform usamplerBuffer u_face_stages;
uniform vec3 u_stage_colors[4];  // Original, Triangulated, Refined, Smoothed

out vec4 frag_color;

void main() {
  vec3 normal = u_flat ? cross(dFdx(v_view_position), dFdy(v_view_position)) : v_view_normal;
  normal = normalize(normal);
  vec3 to_eye = normalize(-v_view_position);
  uint stage = texelFetch(u_face_stages, gl_PrimitiveID).r;
  vec3 base = u_stage_colors[min(stage, 3u)];
  // A file's vertex colours colour the original surface; patches blend them with their stage's
  // colour, so that both the fill and its interpolated colours show.
  if (v_color.a > 0.5) base = stage == 0u ? v_color.rgb : mix(base, v_color.rgb, 0.5);
  if (dot(normal, to_eye) < 0.0) {
    normal = -normal;
    base = base * vec3(0.55, 0.5, 0.6);
  }
  float diffuse = max(dot(normal, to_eye), 0.0);
  vec3 half_vector = normalize(to_eye + vec3(0.3, 0.6, 0.0));
  float specular = pow(max(dot(normal, half_vector), 0.0), 48.0);
  frag_color = vec4(base * (0.22 + 0.78 * diffuse) + vec3(0.18 * specular), 1.0);
}
