// What `holefill fill` and `holefill info` do between loading a mesh and filling it: stitch
// seams, drop small pieces when asked, and tell holes from borders and flat pieces; and the
// lines that tell the user what was found.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "holefill/borders.h"
#include "holefill/components.h"
#include "holefill/holes.h"
#include "holefill/stitch.h"

namespace CLI {
class App;  // CLI11's (CLI/CLI.hpp): only the .cpp files that register options include it
}  // namespace CLI

namespace holefill::cli {

struct PreparationChoice {
  bool stitch = true;                   // --no-stitch turns it off
  StitchOptions stitch_options;         // --stitch-tolerance
  std::size_t remove_pieces_up_to = 0;  // --remove-small-components N (0: keep every piece)
  bool keep_borders = false;            // --keep-borders
};

// What the report says of the mesh's pieces (their face lists are freed before filling).
struct PieceCounts {
  std::size_t pieces = 0;
  std::size_t lone_triangles = 0;
  std::size_t small_pieces = 0;
  std::size_t largest_small_piece = 0;  // faces of the largest small piece (or lone triangle)
};

struct PreparedMesh {
  bool stitched = false;  // stitching ran
  StitchReport stitch;
  RemovedPieces removed;
  PieceCounts pieces;
  std::vector<Hole> holes;         // find_holes after the steps above
  std::vector<LoopClass> classes;  // one per hole
  std::vector<int> ids_to_fill;    // the holes to fill: no flat piece, no border when kept
  std::size_t borders_kept = 0;
  std::size_t pinched_loops = 0;  // loops passing more than once through one vertex
};

// Adds --no-stitch, --stitch-tolerance, --remove-small-components and --keep-borders to
// `command`, writing into `choice` (which must outlive the parse).
void add_preparation_options(CLI::App& command, PreparationChoice& choice);

// Runs the steps on `mesh` and writes what they found to `out` (stderr, like the loader's
// repairs), each line as "holefill: PATH: ...".
PreparedMesh prepare_mesh(Mesh& mesh, const PreparationChoice& choice, const std::string& path,
                          std::ostream& out);

// The note `holefill info` prints beside a loop: its kind, pinches, whether on a small piece.
std::string loop_note(const Hole& hole, const LoopClass& loop_class);

}  // namespace holefill::cli
