#include "preparation.h"

#include <CLI/CLI.hpp>
#include <limits>
#include <ostream>

#include "number_checks.h"
#include "table.h"

namespace holefill::cli {
namespace {

void tell_stitching(const StitchReport& report, const std::string& path, std::ostream& out) {
  if (report.edges_stitched > 0) {
    out << "holefill: " << path << ": stitched " << report.edges_stitched << " boundary edges in "
        << report.seams << (report.seams == 1 ? " seam (" : " seams (") << report.vertices_merged
        << " vertices merged, ";
    if (report.t_junctions > 0) {
      out << report.t_junctions
          << " T-junctions split (a vertex of one side inside an edge of the other), ";
    }
    out << "at most " << format("%.3g", report.largest_distance) << " apart; tolerance "
        << format("%.3g", report.tolerance) << ")\n";
  }
  if (report.edges_left_apart > 0) {
    out << "holefill: " << path << ": " << report.edges_left_apart
        << " boundary edges lie on others but were left apart (more than two meet there, or "
           "joining them would make the mesh non-manifold)\n";
  }
}

void tell_pieces(const PreparedMesh& prepared, const PreparationChoice& choice,
                 const std::string& path, std::ostream& out) {
  if (prepared.removed.pieces > 0) {
    out << "holefill: " << path << ": removed " << prepared.removed.pieces << " pieces of at most "
        << choice.remove_pieces_up_to << " faces (" << prepared.removed.faces << " faces, "
        << prepared.removed.vertices << " vertices)\n";
  }
  const PieceCounts& p = prepared.pieces;
  if (p.lone_triangles + p.small_pieces == 0) return;
  auto count = [](std::size_t n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  out << "holefill: " << path << ": "
      << (p.lone_triangles ? count(p.lone_triangles, "lone triangle") : "")
      << (p.lone_triangles && p.small_pieces ? " and " : "")
      << (p.small_pieces ? count(p.small_pieces, "small floating piece") : "")
      << " beside the surface (--remove-small-components " << p.largest_small_piece
      << " removes them)\n";
}

}  // namespace

void add_preparation_options(CLI::App& command, PreparationChoice& choice) {
  command.add_flag_callback(
      "--no-stitch", [&choice] { choice.stitch = false; },
      "do not stitch seams before finding holes (by default, boundary\n"
      "edges lying on each other in opposite directions are joined\n"
      "where the result stays manifold: unwelded seams, cracks)");
  command
      .add_option("--stitch-tolerance", choice.stitch_options.tolerance,
                  "stitch boundary vertices at most this far apart (0: exact\n"
                  "coincidence only)")
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

PreparedMesh prepare_mesh(Mesh& mesh, const PreparationChoice& choice, const std::string& path,
                          std::ostream& out) {
  PreparedMesh prepared;
  if (choice.stitch) {
    prepared.stitched = true;
    prepared.stitch = stitch_borders(mesh, choice.stitch_options);
    tell_stitching(prepared.stitch, path, out);
  }
  if (choice.remove_pieces_up_to > 0) {
    prepared.removed = remove_small_pieces(mesh, choice.remove_pieces_up_to);
  }
  {  // the pieces' lists (8 bytes a face) are freed before the holes are filled
    const MeshPieces pieces = mesh_pieces(mesh);
    prepared.pieces = {pieces.pieces.size(), pieces.lone_triangles, pieces.small_pieces,
                       pieces.largest_small_piece};
    tell_pieces(prepared, choice, path, out);
    prepared.holes = find_holes(mesh);
    if (separate_touching_holes(mesh, prepared.holes) > 0) prepared.holes = find_holes(mesh);
    prepared.classes = classify_loops(mesh, prepared.holes, pieces);
  }
  for (std::size_t i = 0; i < prepared.holes.size(); ++i) {
    const Hole& hole = prepared.holes[i];
    const LoopClass& c = prepared.classes[i];
    if (hole.repeated_vertices > 0) ++prepared.pinched_loops;
    if (c.kind == LoopKind::FlatPiece) {
      out << "holefill: " << path << ": loop " << hole.id << " is not a hole but " << c.reason
          << "\n";
    } else if (c.kind == LoopKind::Border && choice.keep_borders) {
      ++prepared.borders_kept;
      out << "holefill: " << path << ": loop " << hole.id << " kept open as a border: " << c.reason
          << "\n";
    } else {
      if (c.kind == LoopKind::Border) {
        out << "holefill: " << path << ": loop " << hole.id
            << " looks like the border of an open surface (" << c.reason
            << "); filled, as every loop is by default (--keep-borders leaves it)\n";
      }
      prepared.ids_to_fill.push_back(hole.id);
    }
  }
  return prepared;
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
