// Finding holes, checked against the mesh's boundary halfedges walked by hand: every boundary
// halfedge lies on exactly one loop, loops are closed chains in order, largest first, and their
// measures are the sums they claim to be.
#include "holefill/holes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "holefill/components.h"
#include "holefill/stats.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::make_grid;
using testing::make_icosphere;
using testing::without_faces;

// An icosphere with faces removed at random places (some neighbouring, so loops merge).
Mesh sphere_with_random_holes(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Point> centres;
  for (int i = 0; i < 6; ++i)
    centres.push_back(Point(unit(rng), unit(rng), unit(rng)).normalized());
  return without_faces(make_icosphere(3), [&](const Point& c) {
    return std::any_of(centres.begin(), centres.end(),
                       [&](const Point& centre) { return (c - centre).norm() < 0.2; });
  });
}

TEST(Holes, EveryBoundaryHalfedgeLiesOnExactlyOneClosedLoopLargestFirst) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const Mesh mesh = sphere_with_random_holes(seed);
    const auto holes = find_holes(mesh);
    std::set<int> boundary;
    for (const auto h : mesh.halfedges()) {
      if (mesh.is_boundary(h)) boundary.insert(h.idx());
    }
    ASSERT_FALSE(boundary.empty()) << "seed " << seed;
    std::multiset<int> on_loops;
    for (std::size_t id = 0; id < holes.size(); ++id) {
      const Hole& hole = holes[id];
      EXPECT_EQ(hole.id, static_cast<int>(id));
      ASSERT_EQ(hole.vertices.size(), hole.size());
      if (id > 0) {
        EXPECT_GE(holes[id - 1].size(), hole.size());
      }
      double perimeter = 0.0;
      Point sum(0, 0, 0);
      for (std::size_t i = 0; i < hole.size(); ++i) {
        const HalfedgeHandle h = hole.halfedges[i];
        on_loops.insert(h.idx());
        EXPECT_TRUE(mesh.is_boundary(h));
        EXPECT_EQ(mesh.from_vertex_handle(h), hole.vertices[i]);
        EXPECT_EQ(mesh.to_vertex_handle(h), hole.vertices[(i + 1) % hole.size()]);
        perimeter += (mesh.point(mesh.to_vertex_handle(h)) - mesh.point(hole.vertices[i])).norm();
        sum += mesh.point(hole.vertices[i]);
      }
      EXPECT_NEAR(hole.perimeter, perimeter, 1e-12 * perimeter);
      EXPECT_LT((hole.centroid - sum / static_cast<double>(hole.size())).norm(), 1e-12);
    }
    EXPECT_EQ(on_loops, std::multiset<int>(boundary.begin(), boundary.end())) << "seed " << seed;
  }
}

TEST(Holes, CountHolesIsTheNumberOfLoopsFindHolesGives) {
  EXPECT_EQ(count_holes(make_icosphere(2)), 0u);
  std::size_t loops = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const Mesh mesh = sphere_with_random_holes(seed);
    const std::size_t found = find_holes(mesh).size();
    EXPECT_EQ(count_holes(mesh), found) << "seed " << seed;
    loops += found;
  }
  EXPECT_GT(loops, 8u);
}

TEST(Holes, SurroundingEdgeLengthIsTheMeanOverEachBoundaryVertexsEdges) {
  const Mesh mesh = sphere_with_random_holes(3);
  for (const Hole& hole : find_holes(mesh)) {
    double total = 0.0;
    int count = 0;
    for (const VertexHandle v :
         std::set<VertexHandle>(hole.vertices.begin(), hole.vertices.end())) {
      for (const auto h : mesh.voh_range(v)) {
        total += (mesh.point(mesh.to_vertex_handle(h)) - mesh.point(v)).norm();
        ++count;
      }
    }
    EXPECT_NEAR(hole.mean_surrounding_edge_length, total / count, 1e-12);
  }
}

TEST(Holes, TheLoopThroughAHalfedgeIsFindHolesLoopStartingThere) {
  const Mesh mesh = sphere_with_random_holes(5);
  for (const Hole& hole : find_holes(mesh)) {
    for (std::size_t start = 0; start < hole.size(); start += 3) {
      const Hole through = hole_through(mesh, hole.halfedges[start]);
      EXPECT_EQ(through.id, -1);
      ASSERT_EQ(through.size(), hole.size());
      for (std::size_t i = 0; i < hole.size(); ++i) {
        EXPECT_EQ(through.halfedges[i], hole.halfedges[(start + i) % hole.size()]);
      }
      EXPECT_NEAR(through.perimeter, hole.perimeter, 1e-12);
    }
  }
}

TEST(Holes, TwoSquareHolesMeetingAtACornerArePinchedAndSeparateHolesAreNot) {
  // A 6 x 6 flat grid without cells (1, 1) and (2, 2), which share a corner vertex, and
  // without cell (4, 1), alone.
  const int n = 6;
  const auto cell = [n](const Point& c) {
    return std::pair(static_cast<int>(c[0] * n), static_cast<int>(c[1] * n));
  };
  const Mesh mesh = without_faces(
      testing::make_grid(n + 1, [](double, double) { return 0.0; }), [&](const Point& c) {
        const auto xy = cell(c);
        return xy == std::pair(1, 1) || xy == std::pair(2, 2) || xy == std::pair(4, 1);
      });
  std::map<bool, int> by_pinch;
  for (const Hole& hole : find_holes(mesh)) {
    if (hole.size() == 4 * n) continue;  // the grid's outer border
    EXPECT_EQ(hole.repeated_vertices, hole.size() == 8 ? 1u : 0u) << hole.size();
    ++by_pinch[hole.pinched];
  }
  // Cells (1, 1) and (2, 2) form one loop of 8 edges through their shared corner twice (the
  // corner's fans are joined by no face), or two loops of 4 that touch: pinched either way.
  EXPECT_GE(by_pinch[true], 1);
  EXPECT_EQ(by_pinch[false], 1);  // cell (4, 1)
}

// Removing pieces deletes faces and vertices, which needs OpenMesh's status flags: a Mesh does not
// carry them, so they are requested for the deletion only (the elements are collected, not left
// marked), and a library user's mesh that had some keeps them.
TEST(Pieces, RemovingThemLeavesNoElementMarkedAndTheFlagsAsTheyWere) {
  Mesh plain = sphere_with_random_holes(11);
  const auto a = plain.add_vertex({3.0, 0.0, 0.0}), b = plain.add_vertex({3.5, 0.0, 0.0});
  plain.add_face(a, b, plain.add_vertex({3.0, 0.5, 0.0}));  // a lone triangle
  Mesh flagged = plain;
  flagged.request_face_status();
  const std::size_t faces = plain.n_faces(), vertices = plain.n_vertices();
  for (Mesh* mesh : {&plain, &flagged}) {
    const RemovedPieces removed = remove_small_pieces(*mesh, 1);
    EXPECT_EQ(removed.faces, 1u);
    EXPECT_EQ(removed.vertices, 3u);
    EXPECT_EQ(mesh->n_faces(), faces - 1);
    EXPECT_EQ(mesh->n_vertices(), vertices - 3);
    EXPECT_FALSE(mesh->has_vertex_status());
    EXPECT_FALSE(mesh->has_edge_status());
    EXPECT_FALSE(mesh->has_halfedge_status());
  }
  EXPECT_FALSE(plain.has_face_status());
  EXPECT_TRUE(flagged.has_face_status());
}

// The pieces found by flooding from each face not yet reached through its neighbours (ff_range),
// ordered by their lowest face.
std::vector<std::set<int>> flooded_pieces(const Mesh& mesh) {
  std::vector<std::set<int>> pieces;
  std::set<int> reached;
  for (const auto start : mesh.faces()) {
    if (reached.count(start.idx())) continue;
    std::set<int> piece{start.idx()};
    std::vector<FaceHandle> front{start};
    while (!front.empty()) {
      const FaceHandle f = front.back();
      front.pop_back();
      for (const auto g : mesh.ff_range(f)) {
        if (piece.insert(g.idx()).second) front.push_back(g);
      }
    }
    reached.insert(piece.begin(), piece.end());
    pieces.push_back(piece);
  }
  return pieces;
}

// mesh_pieces against the flood fill: the same pieces in the same order, each face listed once
// in its piece, in face order, the area summed in that order.
void expect_flooded_pieces(const Mesh& mesh) {
  const std::vector<std::set<int>> expected = flooded_pieces(mesh);
  const MeshPieces found = mesh_pieces(mesh);
  ASSERT_EQ(found.pieces.size(), expected.size());
  std::size_t listed = 0;
  for (std::size_t p = 0; p < expected.size(); ++p) {
    const auto faces = found.faces_of(found.pieces[p]);
    std::vector<int> ids;
    double area = 0.0;
    for (const auto f : faces) {
      ids.push_back(f.idx());
      EXPECT_EQ(found.piece_of_face[f.idx()], static_cast<int>(p));
    }
    for (const int f : expected[p]) area += mesh.calc_face_area(FaceHandle(f));
    EXPECT_EQ(ids, std::vector<int>(expected[p].begin(), expected[p].end())) << "piece " << p;
    EXPECT_EQ(found.pieces[p].area, area) << "piece " << p;
    listed += faces.size();
  }
  EXPECT_EQ(listed, found.faces.size());
}

// On a mesh of many pieces, some touching only at a vertex (which does not join them), with a
// deleted face.
TEST(Pieces, AreTheFacesJoinedThroughEdgesAsAFloodFillFindsThem) {
  Mesh mesh = sphere_with_random_holes(11);
  for (int copy = 0; copy < 3; ++copy) {  // three lone triangles, two touching at a vertex
    const auto a = mesh.add_vertex({3.0 + copy, 0.0, 0.0});
    const auto b = mesh.add_vertex({3.5 + copy, 0.0, 0.0});
    mesh.add_face(a, b, mesh.add_vertex({3.0 + copy, 0.5, 0.0}));
    if (copy == 1)
      mesh.add_face(b, mesh.add_vertex({4.5, -1.0, 0.0}), mesh.add_vertex({4.0, -1.0, 0.0}));
  }
  mesh.request_face_status();  // a library user's mesh with OpenMesh's flags, one face deleted
  mesh.request_edge_status();
  mesh.request_halfedge_status();
  mesh.delete_face(FaceHandle(7), false);
  expect_flooded_pieces(mesh);
  EXPECT_GE(flooded_pieces(mesh).size(), 4u);
  EXPECT_EQ(mesh_pieces(mesh).piece_of_face[7], -1);
}

// Several grids whose faces are added in a shuffled order, so that each grid's faces are
// scattered and its lowest face is joined to the others late; and a few vertices no face uses.
Mesh scattered_grids() {
  std::vector<Mesh> grids;
  for (int g = 0; g < 4; ++g) {
    grids.push_back(make_grid(6 + 3 * g, [](double, double) { return 0.0; }));
  }
  Mesh mesh;
  std::vector<std::array<VertexHandle, 3>> faces;
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const int offset = static_cast<int>(mesh.n_vertices());
    for (const auto v : grids[g].vertices()) {
      mesh.add_vertex(grids[g].point(v) + Point(10.0 * static_cast<double>(g), 0.0, 0.0));
    }
    for (const auto f : grids[g].faces()) {
      std::array<VertexHandle, 3> corners;
      int c = 0;
      for (const auto v : grids[g].fv_range(f)) corners[c++] = VertexHandle(v.idx() + offset);
      faces.push_back(corners);
    }
    mesh.add_vertex(Point(10.0 * static_cast<double>(g), -5.0, 0.0));
  }
  std::mt19937 rng(5);
  std::shuffle(faces.begin(), faces.end(), rng);
  for (const auto& corners : faces) mesh.add_face(corners[0], corners[1], corners[2]);
  return mesh;
}

TEST(Pieces, OfScatteredFacesAreNumberedByTheirLowestFace) {
  const Mesh mesh = scattered_grids();
  ASSERT_EQ(mesh.n_faces(), 2u * (5 * 5 + 8 * 8 + 11 * 11 + 14 * 14));
  expect_flooded_pieces(mesh);
  EXPECT_EQ(mesh_pieces(mesh).pieces.size(), 4u);
}

// component_labels against a flood fill along the edges from each vertex not yet reached, in
// vertex order: vertices that no face uses are components of their own.
TEST(Components, AreTheVerticesJoinedByEdgesNumberedByTheirLowestVertex) {
  for (const Mesh& mesh : {scattered_grids(), sphere_with_random_holes(3)}) {
    std::vector<int> expected(mesh.n_vertices(), -1);
    int count = 0;
    for (const auto start : mesh.vertices()) {
      if (expected[start.idx()] >= 0) continue;
      std::vector<VertexHandle> front{start};
      expected[start.idx()] = count;
      while (!front.empty()) {
        const VertexHandle v = front.back();
        front.pop_back();
        for (const auto w : mesh.vv_range(v)) {
          if (expected[w.idx()] < 0) expected[w.idx()] = count, front.push_back(w);
        }
      }
      ++count;
    }
    EXPECT_EQ(component_labels(mesh), expected);
    EXPECT_EQ(connected_components(mesh), static_cast<std::size_t>(count));
  }
  EXPECT_EQ(connected_components(scattered_grids()), 8u);
}

}  // namespace
}  // namespace holefill
