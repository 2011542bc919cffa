#include "preparation.h"

#include <CLI/CLI.hpp>
#include <limits>
#include <ostream>

#include "number_checks.h"

namespace holefill::cli {

void add_preparation_options(CLI::App& command, PreparationChoice& choice) {
  command.add_flag_callback(
      "--no-stitch", [&choice] { choice.stitch = false; },
      "do not stitch seams or weld touching vertices before finding\n"
      "holes (by default, boundary edges lying on each other in\n"
      "opposite directions are joined where the result stays\n"
      "manifold: unwelded seams, cracks; and boundary vertices at one\n"
      "position where holes touch are welded into one)");
  command
      .add_option("--stitch-tolerance", choice.stitch_options.tolerance,
                  "stitch and weld boundary vertices at most this far apart\n"
                  "(0: exact coincidence only)")
      ->default_str("1e-6 x bounding box diagonal")
      ->check(real_number(0.0, std::numeric_limits<double>::max()));
  command
      .add_option("--remove-small-components", choice.remove_pieces_up_to,
                  "remove pieces (faces joined by edges) of at most this many\n"
                  "faces before filling, the largest piece always kept (0: none)")
      ->transform(whole_number(0, std::numeric_limits<std::int64_t>::max()));
  command.add_flag("--keep-borders", choice.keep_borders,
                   "leave open the loops that look like the border of an open\n"
                   "surface (a terrain, a scan, a dome): a piece's widest loop\n"
                   "whose patch would span 40% or more of the piece's area");
}

void add_islands_option(CLI::App& command, std::string& choice) {
  command
      .add_option("--islands", choice,
                  "on: fill each hole with the islands floating in it (one\n"
                  "patch); off: fill every loop on its own")
      ->check(CLI::IsMember({"on", "off"}));
}

PreparedMesh prepare_mesh(Mesh& mesh, const PreparationChoice& choice, const std::string& path,
                          std::ostream& out) {
  PreparedMesh prepared = holefill::prepare_mesh(mesh, choice);
  const auto flag = [](std::size_t faces) {
    return "--remove-small-components " + std::to_string(faces);
  };
  for (const auto& line : preparation_lines(prepared, flag))
    out << "holefill: " << path << ": " << line << "\n";
  return prepared;
}

std::vector<std::string> preparation_lines(
    const PreparedMesh& prepared, const std::function<std::string(std::size_t)>& control_for) {
  std::vector<std::string> lines = prepared.messages;
  if (prepared.pieces_message >= 0) {
    lines.at(static_cast<std::size_t>(prepared.pieces_message)) +=
        "; " + control_for(prepared.pieces.largest_small_piece) + " removes them";
  }
  return lines;
}

std::string loop_note(const Hole& hole, const LoopClass& loop_class) {
  std::string note;
  auto add = [&note](const std::string& part) { note += (note.empty() ? "" : ", ") + part; };
  if (loop_class.kind != LoopKind::Hole) add(to_string(loop_class.kind));
  if (hole.repeated_vertices > 0) {
    add("pinched at " + std::to_string(hole.repeated_vertices) + " vertices");
  } else if (hole.pinched) {
    add("touches another loop");
  }
  if (loop_class.on_small_piece) add("on a small piece");
  return note;
}

}  // namespace holefill::cli
