// Preparing a loaded mesh for filling, the same for the command-line tool, the viewer and the
// library's users: stitch seams (stitch.h) and weld vertices where holes touch (weld.h), drop small
// pieces when asked (components.h), find the holes (holes.h), tell holes from borders and flat
// pieces (borders.h) and find the islands (islands.h); and the lines that tell the user what was
// found.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "holefill/borders.h"
#include "holefill/components.h"
#include "holefill/holes.h"
#include "holefill/islands.h"
#include "holefill/mesh.h"
#include "holefill/stitch.h"
#include "holefill/weld.h"

namespace holefill {

struct PrepareOptions {
  bool stitch = true;                   // stitch seams and weld touching vertices (off: neither)
  StitchOptions stitch_options;         // the tolerance of both
  std::size_t remove_pieces_up_to = 0;  // remove pieces of at most this many faces (0: none)
  bool keep_borders = false;            // leave the loops that look like borders out of the fill
  // The islands the fill will look for (FillOptions::islands): a loop that is an island of a hole
  // being filled is filled with it, so it is neither kept open as a border nor called a flat
  // piece's rim.
  IslandOptions islands;
  // Threads every step may use (stitching's and welding's searches: stitch_options.threads is
  // replaced by this). 0: every core this process may run on. The result is the same whatever
  // the number.
  unsigned threads = 0;
  bool operator==(const PrepareOptions&) const = default;
};

// The mesh's pieces, as the messages and reports count them (their face lists are not kept).
struct PieceCounts {
  std::size_t pieces = 0;
  std::size_t lone_triangles = 0;
  std::size_t small_pieces = 0;
  std::size_t largest_small_piece = 0;  // faces of the largest small piece (or lone triangle)
};

struct PreparedMesh {
  bool stitched = false;  // stitching and welding ran
  StitchReport stitch;
  WeldReport weld;
  RemovedPieces removed;
  PieceCounts pieces;
  std::vector<Hole> holes;         // find_holes after the steps above, touching holes separated
  std::vector<LoopClass> classes;  // one per hole (as the loop looks on its own)
  IslandMap islands;               // find_islands(mesh, holes, options.islands)
  // The holes to fill: no flat piece, no border when kept, except islands of the holes filled
  // (which come with them).
  std::vector<int> ids_to_fill;
  std::size_t borders_kept = 0;
  std::size_t pinched_loops = 0;  // loops passing more than once through one vertex
  // What the steps did and found, one line each, for the user (no file name, no newline). Runs of
  // lines of one kind are summarised past a few, so a million lone triangles give a few lines.
  std::vector<std::string> messages;
  // The index in `messages` of the line about the lone triangles and small pieces left beside
  // the surface (-1: none), which names no control: each front end ends it with its own that
  // removes them (the command line's --remove-small-components N, N = pieces.largest_small_piece;
  // PrepareOptions::remove_pieces_up_to).
  int pieces_message = -1;
};

// Runs the steps on `mesh` in the order above. Expects a mesh without deleted elements (as
// load_mesh gives it). Vertex indices may change where vertices are merged or pieces removed
// (stitch.h, weld.h, components.h say how); every face kept keeps its corners and properties.
PreparedMesh prepare_mesh(Mesh& mesh, const PrepareOptions& options = {});

// After the fill of a prepared mesh: takes back the welds (PreparedMesh::weld) whose holes all
// stayed open (weld.h's unweld_open_pinches), so that no pinch the file did not have is left in the
// output. Returns the line that tells the user (no file name, no newline), empty when nothing
// changed.
std::string undo_unused_welds(Mesh& mesh, const WeldReport& welds);

}  // namespace holefill
