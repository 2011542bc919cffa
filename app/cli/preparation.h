// What `holefill fill` and `holefill info` do between loading a mesh and filling it: the core's
// preparation (holefill/prepare.h, which the viewer runs too), its options on the command line and
// its lines on stderr.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "holefill/prepare.h"

namespace CLI {
class App;  // CLI11's (CLI/CLI.hpp): only the .cpp files that register options include it
}  // namespace CLI

namespace holefill::cli {

// --no-stitch, --stitch-tolerance, --remove-small-components and --keep-borders.
using PreparationChoice = PrepareOptions;

// Adds --no-stitch, --stitch-tolerance, --remove-small-components and --keep-borders to
// `command`, writing into `choice` (which must outlive the parse).
void add_preparation_options(CLI::App& command, PreparationChoice& choice);

// Adds --islands on|off (the islands fill_holes joins to their hole; islands.h), writing into
// `choice` ("on" or "off").
void add_islands_option(CLI::App& command, std::string& choice);

// prepared.messages with the line about small pieces (PreparedMesh::pieces_message) ended by
// "; " + `control` + " removes them": the front end's own control, e.g. the command line's
// "--remove-small-components 4" (what `control_for` makes of pieces.largest_small_piece).
std::vector<std::string> preparation_lines(
    const PreparedMesh& prepared, const std::function<std::string(std::size_t)>& control_for);

// Runs holefill::prepare_mesh on `mesh` and writes what it found to `out` (stderr, like the
// loader's repairs), each line as "holefill: PATH: ..." (preparation_lines, naming
// --remove-small-components).
PreparedMesh prepare_mesh(Mesh& mesh, const PreparationChoice& choice, const std::string& path,
                          std::ostream& out);

// The note `holefill info` prints beside a loop: its kind, pinches, whether on a small piece.
std::string loop_note(const Hole& hole, const LoopClass& loop_class);

}  // namespace holefill::cli
