// Closed CAD-like meshes made in code for the sharp-feature evaluation (README.md): flat faces
// meeting at straight creases and corners, a cylinder's circular rims, and rounded (filleted)
// edges where no crease should appear. Each is triangulated with several vertices along every
// edge and across every face, as a hole filler would see a finely exported part.
#pragma once

#include "holefill/mesh.h"

namespace holefill::features {

// The box [-half, half]^3 with `segments` grid squares along each edge, each square split in two.
Mesh make_box(double half, int segments);

// A cylinder around the z axis, radius `radius`, from z = -half_height to z = half_height:
// `around` vertices on each circle, side rows about as tall as they are wide, flat caps made of
// concentric rings (fewer vertices toward the centre) around a centre vertex.
Mesh make_cylinder(double radius, double half_height, int around);

// A box whose edges and corners are rounded: the points within `fillet` of the box
// [-inner, inner]^3 (edges: quarter cylinders, corners: eighth spheres), half-size inner + fillet.
// `segments` grid squares along each flat face's side, `fillet_segments` across each half of a
// fillet (the grid of a box mapped onto the rounded surface).
Mesh make_rounded_box(double inner, double fillet, int segments, int fillet_segments);

// An L-shaped (stepped) block: [0, 2] x [0, 1] x [0, 2] without the quarter [1, 2] x [0, 1] x
// [1, 2], `per_unit` grid squares per unit length. Convex creases, one concave crease (along
// x = z = 1) and corners where convex and concave creases meet.
Mesh make_step_block(int per_unit);

}  // namespace holefill::features
