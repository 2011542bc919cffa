#version 330 core
// One flat colour; points are drawn as round dots.
uniform vec4 u_color;
uniform bool u_round;
in float v_alpha;  // the wireframe's fade (solid.vert)

out vec4 frag_color;

void main() {
  if (u_round && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  frag_color = vec4(u_color.rgb, u_color.a * v_alpha);
}
