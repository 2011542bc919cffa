// Stitching unwelded seams and zero-width cracks before holes are found (like CGAL's
// stitch_borders): two boundary edges that lie on each other, end to end and in opposite
// directions, become one edge. Pieces exported separately, STL soups and cut-open scans thus
// close where they touch, and only real holes remain for the paper's pipeline. Where one side of
// a crack has vertices the other lacks (T-junctions: CAD faces tessellated one by one), the
// other side's edges are first split at those vertices, so that the two sides match.
#pragma once

#include <cstddef>

#include "holefill/mesh.h"

namespace holefill {

// The default tolerance, relative to the diagonal of the mesh's bounding box: coordinates that
// were one number before two pieces were written out separately (rounded to float, printed with
// a few digits) differ by far less, and real features of a mesh are far larger.
inline constexpr double kDefaultStitchRelativeTolerance = 1e-6;

// The most boundary points that may lie within the tolerance of one boundary point (itself
// included) for its edges to be stitched: a point's partners are looked for among that many
// nearest, so the work stays linear in the boundary however large the tolerance. A point with
// more (a tolerance far above the edge length, or the corner of 64 faces exported one by one)
// has its edges left apart, counted in edges_left_apart.
inline constexpr std::size_t kMostPointsWithin = 64;

struct StitchOptions {
  // Boundary vertices at most this far apart may be merged. Negative: the default,
  // kDefaultStitchRelativeTolerance times the bounding box diagonal. 0: exact coincidence only.
  double tolerance = -1.0;
  // Threads the search for each boundary point's neighbours runs on. 0: every core this process
  // may run on (its affinity mask). The result is the same whatever the number.
  unsigned threads = 0;
};

struct StitchReport {
  double tolerance = 0.0;           // the distance used
  std::size_t edges_stitched = 0;   // pairs of boundary edges that became one edge
  std::size_t seams = 0;            // connected runs of stitched edges
  std::size_t vertices_merged = 0;  // vertices removed, each merged into a vertex it lay on
  double largest_distance = 0.0;    // between a merged vertex and the vertex it was merged into
  // Boundary edges lying on another boundary edge but left apart: more than two lie there, or
  // joining them would make a vertex or an edge non-manifold, or turn a face over, or one of
  // their ends has more than kMostPointsWithin boundary points within the tolerance.
  std::size_t edges_left_apart = 0;
  // Vertices of one side of a crack that lay inside an edge of the other side: that edge was
  // split there (its face in two, both keeping the face's properties) and then stitched.
  std::size_t t_junctions = 0;
};

// Stitches every pair of boundary edges (a->b, b'->a') whose ends lie within the tolerance of
// each other, where the result stays manifold and consistently oriented. Of each group of merged
// vertices the one with the lowest index is kept, with its position and properties; the faces of
// the others are put back on it with all their face and halfedge properties. No vertex that is
// not merged moves, every face keeps its index, and vertices keep their indices except that the
// last ones move into the places of the merged ones (OpenMesh's garbage collection). A
// T-junction's split adds one face after the others (the split face keeps its index); the
// corners at the junction get OBJ texture coordinates and normals interpolated along the edge.
// Splits whose stitch would not be clean are not made. A mesh with nothing to stitch is left
// untouched. Expects a mesh without deleted elements.
StitchReport stitch_borders(Mesh& mesh, const StitchOptions& options = {});

}  // namespace holefill
