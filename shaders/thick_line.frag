#version 330 core
// Boundary colour: the selected hole, a loop filled with it (an island, a hole to bridge to), the
// hovered hole, or any other hole.
flat in int v_hole;

const int kMaxJoined = 16;  // Renderer::kMaxJoined
uniform int u_selected;
uniform int u_joined[kMaxJoined];
uniform int u_joined_count;
uniform int u_hovered;
uniform vec4 u_color;
uniform vec4 u_selected_color;
uniform vec4 u_joined_color;
uniform vec4 u_hovered_color;

out vec4 frag_color;

bool joined() {
  for (int i = 0; i < u_joined_count; ++i) {
    if (u_joined[i] == v_hole) return true;
  }
  return false;
}

void main() {
  frag_color = v_hole == u_selected ? u_selected_color
             : joined()             ? u_joined_color
             : v_hole == u_hovered  ? u_hovered_color
                                    : u_color;
}
