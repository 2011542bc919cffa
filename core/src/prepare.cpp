#include "holefill/prepare.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <utility>

#include "coincident_vertices.h"
#include "holefill/stats.h"
#include "io/two_threads.h"

namespace holefill {
namespace {

// Loops of one kind get a line each up to this many; the rest one line with their count.
constexpr std::size_t kLinesPerKind = 5;

std::string general(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string counted(std::size_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

void tell_stitching(const StitchReport& report, std::vector<std::string>& out) {
  if (report.edges_stitched > 0) {
    std::string line = "stitched " + std::to_string(report.edges_stitched) + " boundary edges in " +
                       counted(report.seams, "seam") + " (" +
                       std::to_string(report.vertices_merged) + " vertices merged, ";
    if (report.t_junctions > 0) {
      line += std::to_string(report.t_junctions) +
              " T-junctions split (a vertex of one side inside an edge of the other), ";
    }
    out.push_back(line + "at most " + general(report.largest_distance) + " apart; tolerance " +
                  general(report.tolerance) + ")");
  }
  if (report.edges_left_apart > 0) {
    out.push_back(std::to_string(report.edges_left_apart) +
                  " boundary edges lie on others but were left apart (more than two meet there, "
                  "or joining them would make the mesh non-manifold)");
  }
}

void tell_welding(const WeldReport& report, std::vector<std::string>& out) {
  if (report.positions > 0) {
    out.push_back("welded " + std::to_string(report.vertices_welded) +
                  (report.vertices_welded == 1 ? " boundary vertex" : " boundary vertices") +
                  " into the vertex at the same position (" + counted(report.positions, "place") +
                  " where holes touch), so that each hole there can be filled");
  }
  if (report.positions_left > 0) {
    out.push_back(counted(report.positions_left, "place") +
                  " where boundary vertices share a position were left apart (welding would "
                  "double an edge or collapse a face, or leave a hole there that passes twice "
                  "through one position)");
  }
}

void tell_pieces(PreparedMesh& prepared, const PrepareOptions& options,
                 std::vector<std::string>& out) {
  if (prepared.removed.pieces > 0) {
    out.push_back("removed " + std::to_string(prepared.removed.pieces) + " pieces of at most " +
                  std::to_string(options.remove_pieces_up_to) + " faces (" +
                  std::to_string(prepared.removed.faces) + " faces, " +
                  std::to_string(prepared.removed.vertices) + " vertices)");
  }
  const PieceCounts& p = prepared.pieces;
  if (p.lone_triangles + p.small_pieces == 0) return;
  // Each front end ends this line with its own control that removes them (pieces_message).
  prepared.pieces_message = static_cast<int>(out.size());
  out.push_back((p.lone_triangles ? counted(p.lone_triangles, "lone triangle") : "") +
                (p.lone_triangles && p.small_pieces ? " and " : "") +
                (p.small_pieces ? counted(p.small_pieces, "small floating piece") : "") +
                " beside the surface, of at most " + counted(p.largest_small_piece, "face"));
}

// The lines about loops of one kind: each of the first few, then how many more there are.
class LoopLines {
 public:
  explicit LoopLines(std::string more) : more_(std::move(more)) {}
  void add(std::string line) {
    if (count_++ < kLinesPerKind) lines_.push_back(std::move(line));
  }
  void flush(std::vector<std::string>& out) const {
    out.insert(out.end(), lines_.begin(), lines_.end());
    if (count_ > kLinesPerKind) {
      out.push_back("... and " + std::to_string(count_ - kLinesPerKind) + " more " + more_);
    }
  }

 private:
  std::string more_;
  std::size_t count_ = 0;
  std::vector<std::string> lines_;
};

// The welded positions whose loops still pass twice through one position (another pair there left
// apart): those holes could not be filled, and their welds would only leave pinches. `holes` gets
// the welded mesh's loops (find_separated_holes).
std::vector<Point> unhelpful_welds(Mesh& mesh, const std::vector<Point>& welded_at,
                                   std::vector<Hole>& holes) {
  holes = find_separated_holes(mesh);
  std::vector<Point> unhelpful;
  for (const auto& hole : holes) {
    if (!detail::coincident_vertices(mesh, hole)) continue;
    for (const auto v : hole.vertices) {
      const Point& p = mesh.point(v);
      if (std::find(welded_at.begin(), welded_at.end(), p) != welded_at.end() &&
          std::find(unhelpful.begin(), unhelpful.end(), p) == unhelpful.end()) {
        unhelpful.push_back(p);
      }
    }
  }
  return unhelpful;
}

// Welds touching vertices (weld.h) where the holes there can then be filled: a weld whose loop
// still passes twice through one position is taken back (the mesh welded again from a copy without
// it), so that no pinch is left that no fill closes. Only meshes with touching vertices pay for the
// copy. `holes` gets the mesh's loops (find_separated_holes) when every weld stays.
WeldReport weld_where_it_helps(Mesh& mesh, double tolerance, unsigned threads,
                               std::optional<std::vector<Hole>>& holes) {
  if (!has_touching_vertices(mesh, tolerance, threads)) return {};
  Mesh unwelded = mesh;
  WeldReport report = weld_touching_vertices(mesh, tolerance, {}, threads);
  std::vector<Hole> welded_holes;
  const std::vector<Point> unhelpful = unhelpful_welds(mesh, report.welded_at, welded_holes);
  if (unhelpful.empty()) {
    holes = std::move(welded_holes);
    return report;
  }
  mesh = std::move(unwelded);
  report = weld_touching_vertices(mesh, tolerance, unhelpful, threads);
  report.positions_left += unhelpful.size();
  return report;
}

// Which loops are filled (PreparedMesh::ids_to_fill) and the lines about the others. A loop that
// is an island of a hole being filled is filled with it whatever it looks like on its own (the rim
// of a small piece looks like a border or a flat piece): no line says it is kept open or never
// filled.
void tell_loops(PreparedMesh& prepared, const PrepareOptions& options) {
  auto filled = [&](std::size_t i) {
    const LoopKind kind = prepared.classes[i].kind;
    return kind == LoopKind::Hole || (kind == LoopKind::Border && !options.keep_borders);
  };
  LoopLines flat("loops that are not holes (the rims of flat pieces)");
  LoopLines kept("loops kept open as borders");
  LoopLines borders("loops that look like the border of an open surface");
  for (std::size_t i = 0; i < prepared.holes.size(); ++i) {
    const Hole& hole = prepared.holes[i];
    const LoopClass& c = prepared.classes[i];
    const std::string loop = "loop " + std::to_string(hole.id);
    if (hole.repeated_vertices > 0) ++prepared.pinched_loops;
    const int outer = prepared.islands.outer[static_cast<std::size_t>(hole.id)];
    if (outer >= 0 && filled(static_cast<std::size_t>(outer))) {
      if (filled(i)) prepared.ids_to_fill.push_back(hole.id);
    } else if (c.kind == LoopKind::FlatPiece) {
      flat.add(loop + " is not a hole but " + c.reason);
    } else if (c.kind == LoopKind::Border && options.keep_borders) {
      ++prepared.borders_kept;
      kept.add(loop + " kept open as a border: " + c.reason);
    } else {
      if (c.kind == LoopKind::Border) {
        borders.add(loop + " looks like the border of an open surface (" + c.reason +
                    "); filled only where a cap does not cut the surface (--keep-borders leaves "
                    "it open)");
      }
      prepared.ids_to_fill.push_back(hole.id);
    }
  }
  flat.flush(prepared.messages);
  kept.flush(prepared.messages);
  borders.flush(prepared.messages);
}

// Whether preparing `mesh` on `threads` threads (0: every core of the process) runs independent
// walks side by side: on a mesh big enough that a thread costs less than it saves.
bool two_threads(const Mesh& mesh, unsigned threads) {
  return threads != 1 && io::use_two_threads(mesh.n_faces(), io::kTwoThreadsFrom);
}

}  // namespace

PreparedMesh prepare_mesh(Mesh& mesh, const PrepareOptions& options) {
  PreparedMesh prepared;
  std::optional<std::vector<Hole>> holes;  // the loops welding found, while the mesh stays so
  if (options.stitch) {
    prepared.stitched = true;
    StitchOptions stitching = options.stitch_options;
    stitching.threads = options.threads;
    prepared.stitch = stitch_borders(mesh, stitching);
    tell_stitching(prepared.stitch, prepared.messages);
    prepared.weld = weld_where_it_helps(mesh, prepared.stitch.tolerance, options.threads, holes);
    tell_welding(prepared.weld, prepared.messages);
  }
  if (options.remove_pieces_up_to > 0) {
    prepared.removed = remove_small_pieces(mesh, options.remove_pieces_up_to);
    if (prepared.removed.pieces > 0) holes.reset();
  }
  std::vector<int> component;  // component_labels, for the islands
  const bool separated = holes.has_value();
  {  // the pieces' lists (8 bytes a face) are freed before the holes are filled
    MeshPieces pieces;
    // Three walks that only read the mesh, the pieces beside the other two.
    io::run_both(
        two_threads(mesh, options.threads), [&] { pieces = mesh_pieces(mesh); },
        [&] {
          if (!holes) holes = find_holes(mesh);
          if (options.islands.detect && holes->size() >= 2) component = component_labels(mesh);
        });
    prepared.pieces = {pieces.pieces.size(), pieces.lone_triangles, pieces.small_pieces,
                       pieces.largest_small_piece};
    tell_pieces(prepared, options, prepared.messages);
    // Separating touching loops only relinks boundaries: the pieces and components stay.
    prepared.holes = separated ? std::move(*holes) : separated_holes(mesh, std::move(*holes));
    prepared.classes = classify_loops(mesh, prepared.holes, pieces);
  }
  // One loop separated into several: their islands are looked for too.
  if (component.empty() && options.islands.detect && prepared.holes.size() >= 2) {
    component = component_labels(mesh);
  }
  prepared.islands = find_islands(mesh, prepared.holes, options.islands, component);
  tell_loops(prepared, options);
  return prepared;
}

std::string undo_unused_welds(Mesh& mesh, const WeldReport& welds) {
  const std::size_t split = unweld_open_pinches(mesh, welds.welded_at);
  if (split == 0) return {};
  return "split " + std::to_string(split) + (split == 1 ? " vertex" : " vertices") +
         " off the welded ones again: the holes that touch there stayed open, so the vertices "
         "there are apart again, as in the file";
}

}  // namespace holefill
