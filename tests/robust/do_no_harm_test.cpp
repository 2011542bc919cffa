// Do no harm (fill.h's FillOptions::allow_intersections, prepare.h): on the meshes every filler
// fails, no patch that intersects the mesh is kept, holes that touch at duplicated vertices are
// welded and closed, and what no clean patch can close is left open exactly as it was, with the
// reason. Each case is built here; intersections are judged by the tests' own brute-force exact
// check (exact_intersections.h), not by the index the library uses.
#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "dirty_meshes.h"
#include "exact_intersections.h"
#include "fill_guarantees.h"
#include "holefill/fill.h"
#include "holefill/io.h"
#include "holefill/prepare.h"
#include "robust_test_util.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

// Removes two faces around point `v` of the soup that share no edge, so that two holes touch at
// v, and gives each of the two fans left around v its own copy of v (at the same position), as
// an exporter that splits vertices writes them. Returns the index of the copy.
int touching_holes_at_a_split_vertex(Soup& soup, int v) {
  std::vector<std::size_t> around;
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    if (std::count(soup.faces[f].begin(), soup.faces[f].end(), v)) around.push_back(f);
  }
  // Neighbours of v in a face's order: the face (v, a, b) joins the fan edge v-a to v-b.
  auto ends = [&](std::size_t f) {
    const auto& face = soup.faces[f];
    const int at = static_cast<int>(std::find(face.begin(), face.end(), v) - face.begin());
    return std::pair(face[(at + 1) % 3], face[(at + 2) % 3]);
  };
  // The ring of faces around v, each followed by the one across its second edge.
  std::vector<std::size_t> ring{around[0]};
  while (ring.size() < around.size()) {
    const int b = ends(ring.back()).second;
    ring.push_back(*std::find_if(around.begin(), around.end(),
                                 [&](std::size_t f) { return ends(f).first == b; }));
  }
  // Remove ring[0] and ring[k] (k = half the ring): the two arcs between them become two fans.
  const std::size_t k = ring.size() / 2;
  const int copy = static_cast<int>(soup.points.size());
  soup.points.push_back(soup.points[v]);
  for (std::size_t i = 1; i < k; ++i) {
    std::replace(soup.faces[ring[i]].begin(), soup.faces[ring[i]].end(), v, copy);
  }
  std::set<std::size_t> removed{ring[0], ring[k]};
  std::vector<std::vector<int>> kept;
  for (std::size_t f = 0; f < soup.faces.size(); ++f) {
    if (!removed.count(f)) kept.push_back(soup.faces[f]);
  }
  soup.faces = std::move(kept);
  return copy;
}

class DoNoHarm : public ScratchTest {};

TEST_F(DoNoHarm, HolesTouchingAtASplitVertexAreWeldedAndBothClosed) {
  const Soup whole = sphere_soup(2);
  for (const int v : {0, 7, 20}) {
    Soup soup = whole;
    touching_holes_at_a_split_vertex(soup, v);
    const auto file = write("touching.obj", obj_text(soup));
    LoadReport report;
    Mesh mesh = load_mesh(file, &report);
    EXPECT_EQ(report.duplicate_positions, 1u);

    // As it is, the two holes are one loop through the position twice: no patch can be added.
    Mesh unwelded = mesh;
    PrepareOptions as_it_is;
    as_it_is.stitch = false;
    const PreparedMesh apart = prepare_mesh(unwelded, as_it_is);
    ASSERT_EQ(apart.holes.size(), 1u);
    const auto refused = fill_holes(unwelded, apart.holes, {});
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_EQ(refused[0].failure.kind, FailureKind::CoincidentPoints) << refused[0].failure;

    // Prepared as the CLI and the viewer do: welded into a pinch, then two holes filled apart.
    const PreparedMesh prepared = prepare_mesh(mesh);
    EXPECT_EQ(prepared.weld.positions, 1u);
    EXPECT_EQ(prepared.weld.vertices_welded, 1u);
    ASSERT_EQ(prepared.holes.size(), 2u) << "vertex " << v;
    EXPECT_EQ(prepared.holes[0].size(), 3u);
    EXPECT_EQ(prepared.holes[1].size(), 3u);
    const Mesh before = mesh;
    const auto fills = fill_holes(mesh, prepared.holes, {});
    ASSERT_EQ(fills.size(), 2u);
    for (const auto& fill : fills) {
      EXPECT_FALSE(fill.failed()) << fill.failure;
      EXPECT_EQ(exact_patch_intersections(mesh, fill.patch.faces), 0u);
    }
    EXPECT_EQ(check_fill_guarantees(before, prepared.holes, mesh, fills), "");
    // Closed again: the sphere's own vertices, every vertex and edge manifold.
    EXPECT_TRUE(find_holes(mesh).empty());
    EXPECT_EQ(mesh.n_vertices(), whole.points.size());
    EXPECT_TRUE(is_oriented_manifold(mesh));
    for (const auto u : mesh.vertices()) EXPECT_TRUE(mesh.is_manifold(u)) << u.idx();

    const CliRun run = run_cli({"fill", file.string(), "-o", path("out.obj")});
    EXPECT_EQ(run.code, cli::kOk) << run.err;
    EXPECT_NE(run.err.find("welded 1 boundary vertex into the vertex at the same position"),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(find_holes(load_mesh(path("out.obj"))).empty());
  }
}

// The corners' positions of every face, in order: what a file's faces say, whatever the indices.
std::vector<std::array<Point, 3>> face_corners(const Mesh& mesh) {
  std::vector<std::array<Point, 3>> corners;
  for (const auto f : mesh.faces()) {
    std::array<Point, 3>& corner = corners.emplace_back();
    int i = 0;
    for (const auto v : mesh.fv_range(f)) corner[i++] = mesh.point(v);
  }
  return corners;
}

TEST_F(DoNoHarm, AWeldWhoseHolesAllStayOpenIsTakenBackAndOneFilledHoleKeepsIt) {
  Soup soup = sphere_soup(2);
  touching_holes_at_a_split_vertex(soup, 7);
  const auto file = write("touching.obj", obj_text(soup));
  const Mesh loaded = load_mesh(file);
  for (const std::size_t filled : {0, 1}) {
    Mesh mesh = loaded;
    const PreparedMesh prepared = prepare_mesh(mesh);
    ASSERT_EQ(prepared.weld.positions, 1u);
    ASSERT_EQ(prepared.holes.size(), 2u);
    HoleSelection selection;
    for (std::size_t i = 0; i < filled; ++i) selection.hole_ids.push_back(prepared.holes[i].id);
    if (filled == 0) selection.max_boundary_edges = 2;  // no hole: both stay open
    const auto fills = fill_holes(mesh, prepared.holes, {}, selection);
    ASSERT_EQ(fills.size(), filled);
    const std::string line = undo_unused_welds(mesh, prepared.weld);
    for (const auto v : mesh.vertices()) EXPECT_TRUE(mesh.is_manifold(v)) << v.idx();
    if (filled == 0) {  // the file's mesh again: its vertices apart, every face as it was
      EXPECT_NE(line.find("split 1 vertex off the welded ones again"), std::string::npos) << line;
      EXPECT_EQ(mesh.n_vertices(), loaded.n_vertices());
      EXPECT_EQ(face_corners(mesh), face_corners(loaded));
      EXPECT_EQ(find_holes(mesh).size(), 1u);
    } else {  // the filled hole joined the two fans: the welded vertex is one fan, and stays
      EXPECT_EQ(line, "");
      EXPECT_EQ(mesh.n_vertices() - fills[0].patch.new_vertices.size(), loaded.n_vertices() - 1);
    }
  }
  const CliRun run = run_cli({"fill", file.string(), "-o", path("out.obj"), "--max-boundary", "2"});
  EXPECT_NE(run.err.find("split 1 vertex off the welded ones again"), std::string::npos) << run.err;
  const Mesh written = load_mesh(path("out.obj"));
  EXPECT_EQ(face_corners(written), face_corners(loaded));
  for (const auto v : written.vertices()) EXPECT_TRUE(written.is_manifold(v)) << v.idx();
}

// A square sheet of two triangles with its lower left corner at `at`.
Soup square_sheet(const Point& at) {
  return {{at, at + Point(1, 0, 0), at + Point(1, 1, 0), at + Point(0, 1, 0)},
          {{0, 1, 2}, {0, 2, 3}}};
}

TEST_F(DoNoHarm, VerticesOfSeparatePiecesTouchingAtAPointAreNotWelded) {
  // Two sheets touching at one corner: one position, two pieces (two objects, not a cut).
  const Soup both = append(square_sheet(Point(0, 0, 0)), square_sheet(Point(1, 1, 0)));
  Mesh mesh = load_mesh(write("apart.obj", obj_text(both)));
  ASSERT_EQ(mesh.n_vertices(), 8u);
  const PreparedMesh prepared = prepare_mesh(mesh);
  EXPECT_EQ(prepared.weld.positions, 0u);
  EXPECT_EQ(mesh.n_vertices(), 8u);
}

// A bumpy height field: the border of an open surface, every cap across which cuts the bumps.
TEST_F(DoNoHarm, AnOpenSurfacesBorderIsLeftOpenWhenEveryCapCutsItAndADomeIsClosed) {
  Mesh terrain = load_mesh(write("terrain.obj", obj_text(terrain_soup(21))));
  const PreparedMesh t = prepare_mesh(terrain);
  ASSERT_EQ(t.holes.size(), 1u);
  EXPECT_EQ(t.classes[0].kind, LoopKind::Border);
  EXPECT_EQ(t.ids_to_fill, std::vector<int>{0});  // borders are tried unless kept
  const Mesh terrain_before = terrain;
  const auto left = fill_holes(terrain, t.holes, {});
  ASSERT_EQ(left.size(), 1u);
  EXPECT_TRUE(left[0].failed());
  EXPECT_GT(left[0].refused_intersections, 0u);
  EXPECT_EQ(check_fill_guarantees(terrain_before, t.holes, terrain, left), "");
  EXPECT_EQ(terrain.n_faces(), terrain_before.n_faces());

  Mesh dome = load_mesh(write("dome.obj", obj_text(dome_soup(3, 0.3))));
  const PreparedMesh d = prepare_mesh(dome);
  ASSERT_EQ(d.holes.size(), 1u);
  const auto closed = fill_holes(dome, d.holes, {});
  ASSERT_EQ(closed.size(), 1u);
  EXPECT_FALSE(closed[0].failed()) << closed[0].failure;
  EXPECT_EQ(exact_patch_intersections(dome, closed[0].patch.faces), 0u);
  EXPECT_TRUE(find_holes(dome).empty());

  // The command line: exit 1, the border named, the output the terrain as it was.
  const CliRun run = run_cli({"fill", path("terrain.obj"), "-o", path("out.obj")});
  EXPECT_EQ(run.code, cli::kSomeHolesNotFilled) << run.err;
  EXPECT_NE(run.err.find("looks like the border of an open surface"), std::string::npos);
  EXPECT_NE(run.err.find("every patch tried intersects the mesh"), std::string::npos) << run.err;
  EXPECT_EQ(load_mesh(path("out.obj")).n_faces(), terrain_before.n_faces());
}

TEST_F(DoNoHarm, ThePreparationSummarisesLoopsOfOneKindPastAFew) {
  // A surface and 40 lone triangles beside it: 40 flat pieces' rims, 5 lines and a count.
  Soup soup = sphere_soup(1);
  for (int i = 0; i < 40; ++i) {
    const int n = static_cast<int>(soup.points.size());
    soup.points.insert(soup.points.end(),
                       {Point(3 + i, 0, 0), Point(3.5 + i, 0, 0), Point(3 + i, 0.5, 0)});
    soup.faces.push_back({n, n + 1, n + 2});
  }
  Mesh mesh = load_mesh(write("lone.obj", obj_text(soup)));
  const PreparedMesh prepared = prepare_mesh(mesh);
  std::size_t rims = 0;
  for (const auto& line : prepared.messages) rims += line.find("is not a hole but") != line.npos;
  EXPECT_EQ(rims, 5u);
  EXPECT_NE(std::find(prepared.messages.begin(), prepared.messages.end(),
                      "... and 35 more loops that are not holes (the rims of flat pieces)"),
            prepared.messages.end());
}

}  // namespace
}  // namespace holefill::testing
