// Welding boundary vertices that lie at one position where no pair of boundary edges joins them,
// so that stitching (stitch.h) does not apply: a loop that touches itself, or two holes cut next to
// each other, in a mesh exported with split vertices. Such a loop passes twice through one position
// and no patch across it can be added; welded, the vertex becomes a pinch whose gaps
// separate_touching_holes (holes.h) turns into loops of their own, each filled apart, so that the
// filled vertex is one fan again.
#pragma once

#include <cstddef>
#include <vector>

#include "holefill/mesh.h"

namespace holefill {

struct WeldReport {
  std::size_t positions = 0;        // positions where vertices were welded
  std::vector<Point> welded_at;     // those positions (each the kept vertex's)
  std::size_t vertices_welded = 0;  // vertices removed, each welded into one it lay on
  std::size_t positions_left = 0;   // positions whose vertices were left apart (below)
};

// Welds boundary vertices at most `tolerance` apart (0: the same coordinates) that belong to one
// piece of the mesh (faces joined by edges: separate objects touching at a point stay apart), when
// no two of them share an edge or a neighbour (a face would collapse, or an edge be doubled) and
// the faces around the welded vertex stay consistently oriented. Of each group the vertex with the
// lowest index is kept, with its position and properties, and the faces of the others are put on
// it with their properties; face indices are kept, vertex indices as stitch_borders keeps them.
// Groups with a vertex at exactly one of `apart`'s positions are left apart (and not counted).
// Expects a mesh without deleted elements; a mesh with nothing to weld is left untouched. The
// search for vertices within the tolerance runs on `threads` threads (0: every core this process
// may run on); the result is the same whatever the number.
WeldReport weld_touching_vertices(Mesh& mesh, double tolerance,
                                  const std::vector<Point>& apart = {}, unsigned threads = 0);

// Takes back the welds whose holes stayed open: each vertex at one of `welded_at`'s positions
// (WeldReport::welded_at) that is still a pinch, its faces in several fans with gaps between them,
// becomes one vertex per fan again, each with the welded vertex's position and properties. The
// fan with the lowest face index stays on the vertex; the others get new vertices at the end.
// Face indices, corners' order and properties are kept. Returns the vertices added (0: the mesh is
// untouched). Expects a mesh without deleted elements.
std::size_t unweld_open_pinches(Mesh& mesh, const std::vector<Point>& welded_at);

// Whether weld_touching_vertices would find any group to judge (a quick look, nothing changed;
// on `threads` threads as there).
bool has_touching_vertices(const Mesh& mesh, double tolerance, unsigned threads = 0);

}  // namespace holefill
