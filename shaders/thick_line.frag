#version 330 core
// Boundary colour: the selected hole, the hovered hole, or any other hole.
flat in int v_hole;

uniform int u_selected;
uniform int u_hovered;
uniform vec4 u_color;
uniform vec4 u_selected_color;
uniform vec4 u_hovered_color;

out vec4 frag_color;

void main() {
  frag_color = v_hole == u_selected ? u_selected_color
             : v_hole == u_hovered  ? u_hovered_color
                                    : u_color;
}
