// Sharp features that enter a hole, and how they continue across it (not in the paper; issue 35).
// A hole cut across the crease of a machined part or the corner of a box is filled by the paper's
// method as a smooth membrane, rounding the crease over. Here the mesh's sharp edges (dihedral
// angle above FeatureOptions::angle_degrees) that end at the hole's boundary are traced outward
// into feature lines, and the lines are matched across the hole:
// - a crease: two lines whose continued directions point at each other, joined by a cubic
//   Hermite curve that matches both tangents (a straight segment for a straight crease, close
//   to a circular arc for a curved one such as a cylinder's rim);
// - a corner: three or more lines whose extensions nearly meet at one point inside the hole,
//   the point nearest all of them (least squares), joined to each line's entry by a segment.
// The fill (fill.h) then places vertices along these curves and fills the regions between them
// separately, each with the curves as a fixed boundary.
#pragma once

#include <string>
#include <vector>

#include "holefill/holes.h"
#include "holefill/mesh.h"

namespace holefill {

struct FeatureOptions {
  // An edge is sharp when the normals of its two faces differ by more than this (degrees; the
  // angle is scale-free). 0 turns feature detection off: every hole is filled as in the paper.
  double angle_degrees = 40.0;
  bool operator==(const FeatureOptions&) const = default;
};

// A feature line entering the hole at one of its boundary vertices.
struct FeatureLine {
  int entry = -1;       // position of its boundary vertex in Hole::vertices
  VertexHandle vertex;  // that vertex
  // The line traced outward along sharp edges (at each vertex the sharp edge that turns least),
  // the entry vertex first: at least 3 points (2 edges), or 2 where the line ends at a corner.
  std::vector<Point> traced;
  Point direction{0.0, 0.0, 0.0};  // unit tangent at the entry, pointing into the hole
  double edge_length = 0.0;        // mean length of the traced edges
  double curvature = 0.0;          // of the circle through its first three points (0: straight)
};

// How lines continue through the hole.
struct FeatureJunction {
  // Indices into HoleFeatures::lines: two for a crease (from the first's entry to the second's),
  // three or more for a corner (in the order of their entries along the hole).
  std::vector<int> lines;
  bool corner = false;
  Point corner_point{0.0, 0.0, 0.0};  // a corner's meeting point
  // The new points along each continued curve, its ends left out: for a crease one path from the
  // first line's entry to the second's; for a corner one path per line, from its entry to the
  // corner point. Spaced at the traced lines' edge length.
  std::vector<std::vector<Point>> paths;
};

struct HoleFeatures {
  std::vector<FeatureLine> lines;          // every feature line found entering the hole
  std::vector<FeatureJunction> junctions;  // how they continue (empty unless all are matched)
  // Why the lines found are not continued (a line without a partner, lines that cross); empty
  // when they are, or when no line was found.
  std::string note;
  bool continued() const { return !junctions.empty() && note.empty(); }
};

// The feature lines that enter `hole` (a boundary loop of `mesh`) and their junctions. Nothing
// when options.angle_degrees is 0 or less, or the loop is pinched or not a plain boundary loop
// of the mesh (a loop joined by bridges). Every line must belong to a junction for any to be
// given; junctions are then non-crossing (each splits the hole in two).
HoleFeatures find_hole_features(const Mesh& mesh, const Hole& hole, const FeatureOptions& options);

// Whether the edge between two faces is sharp under `angle_degrees` (false on a boundary edge).
bool is_sharp_edge(const Mesh& mesh, EdgeHandle edge, double angle_degrees);

}  // namespace holefill
