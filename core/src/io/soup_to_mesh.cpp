#include "soup_to_mesh.h"

#include <numeric>

#include "huge_pages.h"
#include "mesh_from_triangles.h"
#include "repair_checks.h"
#include "soup_attributes.h"
#include "soup_repairs.h"
#include "soup_triangles.h"
#include "two_threads.h"

namespace holefill::io {
namespace {

// Where the mesh's elements came from in the soup (soup_attributes.h), from where they came from
// in the triangles (`sources`), each triangle's polygon and corners, and each vertex's soup
// position (`origin`): those arrays themselves (taken) when the mesh's elements are the triangles'
// and positions' (no face detached: copies of them were 18 MB of a 1M-face textured OBJ's load),
// else composed with the sources, each half of the vertices and faces on its own thread when
// `two`.
SoupOrigins origins_of(const MeshSources& sources, SoupTriangles& triangulation,
                       std::vector<int>& origin, bool track_corners, bool two) {
  SoupOrigins origins;
  if (sources.identity()) {
    origins.vertex = std::move(origin);
    origins.face = std::move(triangulation.face);
    if (track_corners) origins.face_corners = std::move(triangulation.corners);
    return origins;
  }
  // On huge pages, as the mesh's arrays they are read into.
  origins.vertex = huge_page_vector(sources.vertex.size(), 0);
  origins.face = huge_page_vector(sources.face.size(), 0);
  if (track_corners) origins.face_corners = huge_page_vector(sources.face.size(), Triangle{});
  run_in_halves(two, sources.vertex.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) origins.vertex[v] = origin[sources.vertex[v]];
  });
  run_in_halves(two, sources.face.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const int t = sources.face[f];
      origins.face[f] = triangulation.face[t];
      if (track_corners) origins.face_corners[f] = triangulation.corners[t];
    }
  });
  return origins;
}

}  // namespace

// Where each triangle and vertex came from is followed only when the soup carries attributes to
// copy: on a big mesh with none, those arrays were a tenth of the peak.
Mesh build_mesh(Soup soup, LoadReport& report, std::size_t two_threads_from) {
  const bool track_origins = has_attributes(soup);
  const bool track_corners = has_corner_values(soup);
  const bool two = use_two_threads(soup.face_count(), two_threads_from);
  SoupTriangles triangulation = triangulate_soup(soup, track_origins, track_corners, two, report);
  // The polygons are triangles now.
  std::vector<int>().swap(soup.corners);
  std::vector<std::size_t>().swap(soup.face_end);
  soup.face_line = FaceLines();
  // The triangles' edges beside the duplicate positions. Two triangles with the same corners in
  // the same cyclic order run the same way along an edge that only they use, or share it with
  // others: where no edge is so, there are no duplicate triangles to look for (the hash of every
  // triangle was the largest serial cost of loading a clean 1.4M-face mesh).
  const bool count_positions = report.format != "stl";
  const unsigned threads = two ? 2 : 1;
  std::size_t duplicate_positions = 0;
  EdgeUses uses;
  bool manifold_edges = true;
  run_both(
      two,
      [&] {
        uses = EdgeUses(triangulation.triangles);
        manifold_edges = !any_non_manifold_edge(uses, 1);
      },
      [&] {
        if (count_positions) duplicate_positions = count_duplicate_positions(soup.positions);
      });
  report.duplicate_positions = duplicate_positions;
  if (!manifold_edges) {
    uses = EdgeUses();  // not held beside the duplicates' table
    report.duplicate_faces_dropped = drop_duplicate_triangles(
        triangulation.triangles, triangulation.face, triangulation.corners);
    uses = EdgeUses(triangulation.triangles, threads);
  }
  std::vector<Point> positions = std::move(soup.positions);
  const std::size_t original_vertices = positions.size();
  std::vector<int> origin;  // the soup position of each vertex, when tracked
  if (track_origins) {
    reserve_on_huge_pages(origin, positions.size());
    origin.resize(positions.size());
    std::iota(origin.begin(), origin.end(), 0);
  }
  std::vector<char> detached =
      make_consistent(triangulation.triangles, triangulation.corners, positions, origin, report,
                      uses, manifold_edges, threads);
  MeshSources sources;
  Mesh mesh =
      assemble(std::move(positions), std::move(triangulation.triangles), std::move(detached),
               original_vertices, report, track_origins ? &sources : nullptr, std::move(uses),
               two_threads_from, [&soup](Mesh& empty) { add_soup_properties(soup, empty); });
  keep_file_format(soup, mesh);
  if (!track_origins) return mesh;
  const SoupOrigins origins = origins_of(sources, triangulation, origin, track_corners, two);
  copy_soup_attributes(soup, origins, mesh, two);
  return mesh;
}

void add_warnings(LoadReport& report) {
  auto warn = [&report](std::size_t count, const std::string& text) {
    if (count) report.warnings.push_back(std::to_string(count) + " " + text);
  };
  warn(report.polygons_triangulated, "polygons with more than 3 corners were triangulated");
  warn(report.degenerate_faces_dropped,
       "degenerate faces (a vertex used twice, or fewer than 3 corners) were dropped");
  warn(report.duplicate_faces_dropped,
       "duplicate faces (the same corners as an earlier face) were dropped");
  warn(report.faces_flipped,
       "faces were flipped to agree with the orientation of their neighbours");
  warn(report.faces_detached, "non-manifold faces were kept on their own copies of their vertices");
  warn(report.vertices_split,
       "vertices where closed surfaces touch were split, one copy per surface");
  warn(report.duplicate_positions,
       "vertices have exactly the position of another vertex (kept apart: the surface may be "
       "cut open there)");
  warn(report.isolated_vertices, "vertices are used by no face (kept)");
  warn(report.elements_ignored, "line, point or curve elements were ignored (not surfaces)");
}

}  // namespace holefill::io
