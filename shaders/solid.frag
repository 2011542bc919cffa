#version 330 core
// One flat colour; points are drawn as round dots.
uniform vec4 u_color;
uniform bool u_round;

out vec4 frag_color;

void main() {
  if (u_round && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  frag_color = u_color;
}
