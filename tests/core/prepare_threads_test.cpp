// Preparing a big mesh on several threads (prepare.h: the pieces beside the holes and the
// components of the islands) finds what the steps find one after the other on one thread.
#include <gtest/gtest.h>

#include <cmath>

#include "holefill/components.h"
#include "holefill/prepare.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::Cap;

// An icosphere of 81,920 faces (above the size from which preparing uses a second thread) with
// two holes holding islands (two pieces floating in one, one in the other), small holes
// scattered over it and a lone triangle floating apart: several pieces, many loops, islands.
Mesh many_pieces_and_holes() {
  const auto unit = [](const Point&) { return 1.0; };
  const Mesh islands = testing::cut_around_islands(
      testing::make_blob(6, unit), {Point(0, 0, 1), 0.7},
      {{Point(0.2, 0, 1).normalized(), 0.2}, {Point(-0.2, 0, 1).normalized(), 0.15}});
  Mesh mesh =
      testing::cut_around_islands(islands, {Point(0, 0, -1), 0.5}, {{Point(0, 0, -1), 0.2}});
  mesh = testing::without_faces(mesh, [](const Point& c) {
    return c[2] > -0.6 && c[2] < 0.6 && std::fmod(std::abs(c[0] * 7.0 + c[1] * 3.0), 0.9) < 0.02;
  });
  const auto a = mesh.add_vertex(Point(3, 0, 0)), b = mesh.add_vertex(Point(3, 1, 0)),
             c = mesh.add_vertex(Point(3, 0, 1));
  mesh.add_face(a, b, c);
  return mesh;
}

void expect_same_holes(const std::vector<Hole>& a, const std::vector<Hole>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    EXPECT_EQ(a[i].halfedges, b[i].halfedges);
    EXPECT_EQ(a[i].pinched, b[i].pinched);
  }
}

TEST(PrepareThreads, ThePiecesHolesAndIslandsAreTheStepsOneAfterTheOther) {
  const Mesh original = many_pieces_and_holes();
  ASSERT_GE(original.n_faces(), std::size_t{1} << 16);
  // The steps prepare_mesh takes after stitching, called one by one on a copy.
  Mesh stepwise = original;
  const MeshPieces pieces = mesh_pieces(stepwise);
  const std::vector<Hole> holes = find_separated_holes(stepwise);
  const IslandMap islands = find_islands(stepwise, holes, IslandOptions{});
  ASSERT_GT(pieces.pieces.size(), 3u);
  ASSERT_GT(holes.size(), 10u);
  ASSERT_GT(std::count(islands.outer.begin(), islands.outer.end(), -1),
            0);  // some loops are islands, the others not
  ASSERT_LT(static_cast<std::size_t>(std::count(islands.outer.begin(), islands.outer.end(), -1)),
            holes.size());
  PreparedMesh first;
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    SCOPED_TRACE(threads);
    Mesh mesh = original;
    PrepareOptions options;
    options.stitch = false;  // the mesh as it is: the steps above
    options.threads = threads;
    const PreparedMesh prepared = prepare_mesh(mesh, options);
    EXPECT_EQ(prepared.pieces.pieces, pieces.pieces.size());
    EXPECT_EQ(prepared.pieces.lone_triangles, pieces.lone_triangles);
    EXPECT_EQ(prepared.pieces.small_pieces, pieces.small_pieces);
    expect_same_holes(prepared.holes, holes);
    EXPECT_EQ(prepared.islands.outer, islands.outer);
    EXPECT_EQ(prepared.islands.islands, islands.islands);
    EXPECT_EQ(prepared.islands.note, islands.note);
    if (threads == 1) first = prepared;
    EXPECT_EQ(prepared.messages, first.messages);
    EXPECT_EQ(prepared.ids_to_fill, first.ids_to_fill);
  }
}

}  // namespace
}  // namespace holefill
