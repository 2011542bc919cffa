// Stitching: seams and cracks of generated dirty meshes are zipped back into exactly
// the surface they were cut from, and nothing else is joined.
#include "holefill/stitch.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <numbers>
#include <tuple>

#include "dirty_meshes.h"
#include "holefill/holes.h"
#include "holefill/obj_attributes.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

class Stitch : public ScratchTest {
 protected:
  Mesh load(const Soup& soup) const { return load_mesh(write("input.obj", obj_text(soup))); }
};

// The corner positions of every face, in face order, bit for bit.
std::vector<std::array<Point, 3>> face_corners(const Mesh& mesh) {
  std::vector<std::array<Point, 3>> corners;
  for (const auto f : mesh.faces()) {
    std::array<Point, 3> c;
    int i = 0;
    for (const auto v : mesh.fv_range(f)) c[i++ % 3] = mesh.point(v);
    corners.push_back(c);
  }
  return corners;
}

bool same_bits(const std::vector<std::array<Point, 3>>& a,
               const std::vector<std::array<Point, 3>>& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(std::array<Point, 3>)) == 0;
}

TEST_F(Stitch, ASeamDuplicatedAlongACutIsZippedBackIntoTheSurfaceItWasCutFrom) {
  const Soup whole = sphere_soup(3);
  Soup cut = whole;
  std::mt19937 rng(1);
  const std::size_t copies = cut_apart(
      cut, [](const Point& c) { return c[2] > 0.3 * c[0] + 0.1; }, 0.0, rng);
  ASSERT_GT(copies, 10u);
  Mesh mesh = load(cut);
  ASSERT_EQ(find_holes(mesh).size(), 2u);
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.vertices_merged, copies);
  EXPECT_EQ(report.edges_stitched, copies);  // the cut is a closed loop: as many edges as points
  EXPECT_EQ(report.seams, 1u);
  EXPECT_EQ(report.largest_distance, 0.0);
  EXPECT_EQ(report.edges_left_apart, 0u);
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_TRUE(is_oriented_manifold(mesh));
  EXPECT_EQ(mesh.n_vertices(), whole.points.size());
  // Every face keeps its index and its corners' positions.
  EXPECT_TRUE(same_bits(face_corners(mesh), face_corners(load(whole))));
}

TEST_F(Stitch, ACrackWhoseSidesAreAHairApartIsZippedOntoTheOlderVertices) {
  const Soup whole = terrain_soup(11);
  Soup cracked = whole;
  std::mt19937 rng(2);
  const std::size_t copies = cut_apart(
      cracked, [](const Point& c) { return c[0] > 0.5; }, 1e-7, rng,
      [](const Point& p) { return std::abs(p[0] - 0.5) < 1e-9 && p[1] > 0.3 && p[1] < 0.7; });
  ASSERT_EQ(copies, 3u);  // y = 0.4, 0.5, 0.6: a crack of four edges per side
  Mesh mesh = load(cracked);
  ASSERT_EQ(find_holes(mesh).size(), 2u);  // the border and the crack
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.vertices_merged, 3u);
  EXPECT_EQ(report.edges_stitched, 4u);
  EXPECT_NEAR(report.largest_distance, 1e-7, 1e-12);
  EXPECT_EQ(find_holes(mesh).size(), 1u);
  EXPECT_TRUE(is_oriented_manifold(mesh));
  EXPECT_TRUE(same_bits(face_corners(mesh), face_corners(load(whole))));
}

TEST_F(Stitch, ABoxExportedFaceByFaceBecomesOneClosedBox) {
  const int n = 4;
  Mesh mesh = load(box_of_separate_faces(n));
  ASSERT_EQ(find_holes(mesh).size(), 6u);
  const StitchReport report = stitch_borders(mesh);
  const std::size_t box_vertices = 6 * (n - 2) * (n - 2) + 12 * (n - 2) + 8;
  EXPECT_EQ(mesh.n_vertices(), box_vertices);
  EXPECT_EQ(report.vertices_merged, 6u * n * n - box_vertices);
  EXPECT_EQ(report.edges_stitched, 12u * (n - 1));
  EXPECT_EQ(report.seams, 1u);  // the twelve seams meet at the corners
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_TRUE(is_oriented_manifold(mesh));
}

TEST_F(Stitch, GapsWiderThanTheToleranceStayOpenAndTheMeshUntouched) {
  Soup cut = sphere_soup(2);
  std::mt19937 rng(3);
  const std::size_t copies = cut_apart(
      cut, [](const Point& c) { return c[1] > 0.2; }, 1e-3, rng);
  Mesh mesh = load(cut);
  const Mesh before = mesh;
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.edges_stitched, 0u);
  EXPECT_NEAR(report.tolerance, 1e-6 * 2 * std::sqrt(3.0), 1e-8);  // the bounding box is ~[-1,1]^3
  EXPECT_TRUE(original_part_unchanged(before, mesh));
  EXPECT_EQ(mesh.n_vertices(), before.n_vertices());

  StitchOptions wider;
  wider.tolerance = 2e-3;
  const StitchReport stitched = stitch_borders(mesh, wider);
  EXPECT_EQ(stitched.vertices_merged, copies);
  EXPECT_LE(stitched.largest_distance, 1e-3 * (1 + 1e-12));
  EXPECT_TRUE(find_holes(mesh).empty());
}

TEST_F(Stitch, ExactCoincidenceOnlyWithAZeroTolerance) {
  Soup cut = sphere_soup(2);
  std::mt19937 rng(4);
  cut_apart(
      cut, [](const Point& c) { return c[0] > 0.0; }, 1e-9, rng);
  Mesh mesh = load(cut);
  StitchOptions exact;
  exact.tolerance = 0.0;
  EXPECT_EQ(stitch_borders(mesh, exact).edges_stitched, 0u);
  EXPECT_GT(stitch_borders(mesh).edges_stitched, 0u);
}

// Three strips meeting along the x axis, each with its own points on it, the middle one facing
// the other way (so that each of its edges there could join either neighbour).
Soup three_fins() {
  Soup fins;
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * std::numbers::pi * k / 3;
    const Point out(0, std::cos(a), std::sin(a));
    Soup strip;
    for (int i = 0; i < 4; ++i) {
      strip.points.emplace_back(i, 0, 0);
      strip.points.push_back(Point(i, 0, 0) + out);
    }
    for (int i = 0; i < 3; ++i) {
      strip.faces.push_back({2 * i, 2 * i + 2, 2 * i + 1});
      strip.faces.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
      if (k == 1) {
        std::swap(strip.faces.rbegin()[0][1], strip.faces.rbegin()[0][2]);
        std::swap(strip.faces.rbegin()[1][1], strip.faces.rbegin()[1][2]);
      }
    }
    fins = append(std::move(fins), strip);
  }
  return fins;
}

TEST_F(Stitch, ThreeSheetsMeetingOnOneLineAreLeftApart) {
  Mesh mesh = load(three_fins());
  const Mesh before = mesh;
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.edges_stitched, 0u);
  EXPECT_EQ(report.edges_left_apart, 9u);  // three edges on the line in each of the strips
  EXPECT_TRUE(original_part_unchanged(before, mesh));
}

TEST_F(Stitch, PiecesTouchingAtOnePointOnlyAreNotMerged) {
  // Two triangles with one corner at the same place: merging it would make a bowtie vertex.
  const Soup soup{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {-1, 0, 0}, {0, -1, 0}},
                  {{0, 1, 2}, {3, 4, 5}}};
  Mesh mesh = load(soup);
  EXPECT_EQ(stitch_borders(mesh).vertices_merged, 0u);
  EXPECT_EQ(mesh.n_vertices(), 6u);
}

TEST_F(Stitch, EdgesRunningTheSameWayAreNotJoined) {
  // Two squares side by side, the second turned over: joining them would need a face flipped.
  Mesh mesh;
  std::vector<VertexHandle> v;
  for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                         Point(1, 0, 0), Point(2, 0, 0), Point(2, 1, 0), Point(1, 1, 0)}) {
    v.push_back(mesh.add_vertex(p));
  }
  mesh.add_face(v[0], v[1], v[2]);
  mesh.add_face(v[0], v[2], v[3]);
  mesh.add_face(v[4], v[6], v[5]);
  mesh.add_face(v[4], v[7], v[6]);
  EXPECT_EQ(stitch_borders(mesh).edges_stitched, 0u);
  EXPECT_EQ(mesh.n_vertices(), 8u);
}

TEST_F(Stitch, AShortEdgeOnABoundaryIsNeverCollapsed) {
  // A fan whose rim has two points 1e-9 apart, joined by an edge.
  Mesh mesh;
  const auto centre = mesh.add_vertex(Point(0, 0, 1));
  std::vector<VertexHandle> rim;
  for (const double a : {0.0, 1e-9, 2.0, 4.0}) {
    rim.push_back(mesh.add_vertex(Point(std::cos(a), std::sin(a), 0)));
  }
  for (std::size_t i = 0; i < rim.size(); ++i) {
    mesh.add_face(centre, rim[i], rim[(i + 1) % rim.size()]);
  }
  StitchOptions generous;
  generous.tolerance = 1e-3;
  EXPECT_EQ(stitch_borders(mesh, generous).vertices_merged, 0u);
  EXPECT_EQ(mesh.n_vertices(), 5u);
}

TEST_F(Stitch, FaceAndHalfedgePropertiesTravelWithTheirFaces) {
  Soup cut = sphere_soup(2);
  std::mt19937 rng(5);
  cut_apart(
      cut, [](const Point& c) { return c[2] > 0.0; }, 0.0, rng);
  Mesh mesh = load(cut);
  OpenMesh::FPropHandleT<int> face_id;
  OpenMesh::HPropHandleT<Point> corner_at;  // the position of the corner a face halfedge leaves
  OpenMesh::VPropHandleT<int> vertex_id;
  mesh.add_property(face_id);
  mesh.add_property(corner_at);
  mesh.add_property(vertex_id);
  mesh.request_halfedge_texcoords2D();
  for (const auto f : mesh.faces()) {
    mesh.property(face_id, f) = f.idx();
    for (const auto h : mesh.fh_range(f)) {
      mesh.property(corner_at, h) = mesh.point(mesh.from_vertex_handle(h));
      mesh.set_texcoord2D(
          h, Mesh::TexCoord2D(float(f.idx()), float(mesh.from_vertex_handle(h).idx())));
    }
  }
  std::map<std::array<double, 3>, int> kept_id;  // the lowest vertex index at each position
  for (const auto v : mesh.vertices()) {
    mesh.property(vertex_id, v) = 1000 + v.idx();
    const Point& p = mesh.point(v);
    kept_id.emplace(std::array<double, 3>{p[0], p[1], p[2]}, v.idx());
  }
  ASSERT_GT(stitch_borders(mesh).vertices_merged, 0u);
  ASSERT_TRUE(find_holes(mesh).empty());
  // The merge deleted faces with status flags requested for it: none is left marked.
  EXPECT_FALSE(mesh.has_face_status() || mesh.has_vertex_status());
  for (const auto f : mesh.faces()) {
    EXPECT_EQ(mesh.property(face_id, f), f.idx());
    for (const auto h : mesh.fh_range(f)) {
      EXPECT_EQ(mesh.property(corner_at, h), mesh.point(mesh.from_vertex_handle(h)));
      EXPECT_EQ(mesh.texcoord2D(h)[0], float(f.idx()));
    }
  }
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    EXPECT_EQ(mesh.property(vertex_id, v), 1000 + kept_id.at({p[0], p[1], p[2]}));
  }
}

// The positions where only one side of a box of separate sides has a point on a box edge (not at
// a corner): the T-junctions, found by brute force over the soup.
std::size_t lone_points_on_box_edges(const Soup& box, const std::array<int, 6>& points_per_side) {
  auto on_box_edge = [](const Point& p) {
    int at_face = 0;
    for (int axis = 0; axis < 3; ++axis) at_face += p[axis] == 0.0 || p[axis] == 1.0;
    return at_face == 2;
  };
  std::size_t lone = 0, first = 0;
  for (std::size_t side = 0; side < 6; ++side) {
    const std::size_t count = std::size_t(points_per_side[side]) * points_per_side[side];
    for (std::size_t i = first; i < first + count; ++i) {
      if (!on_box_edge(box.points[i])) continue;
      std::size_t sides_there = 0;
      for (const Point& q : box.points) sides_there += (q - box.points[i]).norm() < 1e-12;
      lone += sides_there == 1;
    }
    first += count;
  }
  return lone;
}

double total_area(const Mesh& mesh) {
  double area = 0.0;
  for (const auto f : mesh.faces()) area += mesh.calc_face_area(f);
  return area;
}

TEST_F(Stitch, ABoxWhoseSidesWereTessellatedApartClosesAtItsTJunctions) {
  // Sides of 2 to 6 points a row: where 3 meets 4, 4 meets 5, ... the points interleave, so each
  // side's edges hold the other's points (a zipper); where 2 meets 3, only one side has any. With
  // 41 and 60 a row, the ball around a long edge holds hundreds of points: the search halves it.
  for (const std::array<int, 6>& sides :
       {std::array<int, 6>{3, 4, 5, 2, 6, 3}, std::array<int, 6>{2, 2, 5, 5, 3, 4},
        std::array<int, 6>{2, 41, 60, 2, 41, 60}}) {
    const Soup box = box_of_separate_faces(sides);
    Mesh mesh = load(box);
    const StitchReport report = stitch_borders(mesh);
    EXPECT_EQ(report.t_junctions, lone_points_on_box_edges(box, sides));
    EXPECT_GT(report.t_junctions, 0u);
    EXPECT_TRUE(find_holes(mesh).empty());
    EXPECT_TRUE(is_oriented_manifold(mesh));
    EXPECT_EQ(int(mesh.n_vertices()) - int(mesh.n_edges()) + int(mesh.n_faces()), 2);
    EXPECT_NEAR(total_area(mesh), 6.0, 1e-12);  // nothing folded over, nothing missing
    // No sliver beyond the input's own: rows of 41 and 60 points interleave 1/2360 apart, which
    // makes triangles of 0.5 / 59 / 2360 = 3.6e-6; rows of at most 6 points, none below 1e-3.
    const bool fine = *std::max_element(sides.begin(), sides.end()) > 6;
    for (const auto f : mesh.faces()) EXPECT_GT(mesh.calc_face_area(f), fine ? 3e-6 : 1e-3);
    // One vertex per distinct position of the soup, and none added.
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < box.points.size(); ++i) {
      bool seen = false;
      for (std::size_t j = 0; j < i && !seen; ++j)
        seen = (box.points[j] - box.points[i]).norm() < 1e-12;
      distinct += !seen;
    }
    EXPECT_EQ(mesh.n_vertices(), distinct);
    EXPECT_EQ(report.vertices_merged, box.points.size() - distinct);
    EXPECT_EQ(mesh.n_faces(), box.faces.size() + report.t_junctions);
  }
}

// The T-junctions are searched in blocks of halfedges on the threads given: the box of rows of 41
// and 60 points (about 120,000 halfedges, several blocks) stitches into the same mesh on any
// number of threads, face for face.
TEST_F(Stitch, TJunctionsAreTheSameOnOneTwoThreeAndManyThreads) {
  const std::array<int, 6> sides{2, 41, 60, 2, 41, 60};
  const Soup box = box_of_separate_faces(sides);
  auto stitched = [&](unsigned threads) {
    Mesh mesh = load(box);
    StitchOptions options;
    options.threads = threads;
    const StitchReport report = stitch_borders(mesh, options);
    std::vector<double> positions;
    for (const auto v : mesh.vertices()) {
      positions.insert(positions.end(), mesh.point(v).data(), mesh.point(v).data() + 3);
    }
    std::vector<int> corners;
    for (const auto f : mesh.faces()) {
      for (const auto v : mesh.fv_range(f)) corners.push_back(v.idx());
    }
    return std::tuple(report.t_junctions, report.edges_stitched, positions, corners);
  };
  const auto one = stitched(1);
  ASSERT_EQ(std::get<0>(one), lone_points_on_box_edges(box, sides));
  ASSERT_GT(load(box).n_halfedges(), std::size_t{1} << 15);  // more than one block
  for (const unsigned threads : {2u, 3u, 64u}) EXPECT_EQ(stitched(threads), one) << threads;
}

// Two unit squares side by side; the left one has a vertex halfway up the edge they share
// (vertex 3 of the OBJ), the right one has none there. Texture coordinates per corner.
constexpr const char* kTJunctionObj =
    "v 0 0 0\nv 1 0 0\nv 1 0.5 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
    "vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0.5 1\nvt 0 1\nvt 1 0\nvt 1 1\nvt 0.9 0.2\nvt 0.9 0.6\n"
    "usemtl left\nf 1/1 2/2 3/3\nf 1/1 3/3 5/5\nf 3/3 4/4 5/5\n"
    "usemtl right\nf 2/8 6/6 7/7\nf 2/8 7/7 4/9\n";

TEST_F(Stitch, ATJunctionSplitKeepsTheFaceAndInterpolatesItsCorners) {
  Mesh mesh = load_mesh(write("t.obj", kTJunctionObj));
  const Mesh before = mesh;
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.t_junctions, 1u);
  EXPECT_EQ(report.edges_stitched, 2u);
  EXPECT_EQ(report.vertices_merged, 0u);
  ASSERT_EQ(find_holes(mesh).size(), 1u);  // only the outer border is left
  ASSERT_EQ(mesh.n_vertices(), 7u);
  ASSERT_EQ(mesh.n_faces(), 6u);
  const ObjHandles obj = obj_handles(mesh);
  const ObjTables& tables = mesh.property(obj.tables);
  // The faces of the left square and their corners are as they were.
  for (int f = 0; f < 3; ++f) {
    for (const auto h : mesh.fh_range(FaceHandle(f))) {
      const auto old =
          before.find_halfedge(before.from_vertex_handle(h), before.to_vertex_handle(h));
      EXPECT_EQ(mesh.property(obj.texcoord, h), before.property(obj.texcoord, old));
    }
  }
  // The right square's faces now meet vertex 3 (index 2): both halves keep the material, and their
  // corner there lies halfway between the split face's corners at (1,0) and (1,1): vt 8 and vt 9.
  int corners_at_junction = 0;
  for (const auto f : mesh.faces()) {
    if (f.idx() < 3) continue;
    EXPECT_EQ(tables.materials[mesh.property(obj.material, f) - 1], "right");
    for (const auto h : mesh.fh_range(f)) {
      if (mesh.to_vertex_handle(h).idx() != 2) continue;
      ++corners_at_junction;
      const auto& uv = tables.texcoords[mesh.property(obj.texcoord, h) - 1];
      EXPECT_NEAR(uv[0], 0.9, 1e-15);
      EXPECT_NEAR(uv[1], 0.4, 1e-15);
    }
  }
  EXPECT_EQ(corners_at_junction, 2);
  EXPECT_NEAR(total_area(mesh), 2.0, 1e-15);
}

TEST_F(Stitch, AVertexOnAnEdgeWhoseBorderDoesNotRunBackAlongItIsNoTJunction) {
  // A triangle whose tip touches the middle of a square's boundary edge from outside (a fin
  // leaning on it, its border leaving the edge at once): nothing to stitch, nothing split.
  const Soup soup{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0.5, 0}, {2, 0, 0.5}, {2, 1, 0.5}},
      {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}}};
  Mesh mesh = load(soup);
  const Mesh before = mesh;
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.t_junctions, 0u);
  EXPECT_EQ(mesh.n_faces(), 3u);
  EXPECT_TRUE(same_bits(face_corners(mesh), face_corners(before)));
}

// Strips along the x axis from 0 to 2 with a vertex at x = 1, their border running from 0 to 2,
// each turned about the axis by its own angle (degrees): the fine side of a crack.
Soup fins_along_x_axis(std::initializer_list<double> angles) {
  Soup fins;
  for (const double degrees : angles) {
    const double a = degrees * std::numbers::pi / 180.0;
    const Point out(0, std::cos(a), std::sin(a));
    Soup fin{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, Point(1, 0, 0) + out}, {{0, 3, 1}, {1, 3, 2}}};
    fins = append(std::move(fins), fin);
  }
  return fins;
}

TEST_F(Stitch, AnEdgeThatAlreadyHasAPartnerIsNotSplitForAThirdSheet) {
  // Two triangles share the long edge from (0,0,0) to (2,0,0) end to end; a fin standing on that
  // edge has a vertex in its middle. The triangles are stitched to each other, the fin left apart.
  const Soup triangles{{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {0, 0, 0}, {2, 0, 0}, {1, -1, 0}},
                       {{0, 1, 2}, {3, 5, 4}}};
  Mesh mesh = load(append(triangles, fins_along_x_axis({-90})));
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.t_junctions, 0u);
  EXPECT_EQ(report.edges_stitched, 1u);
  EXPECT_EQ(mesh.n_faces(), 4u);
}

TEST_F(Stitch, AnEdgeWithTwoSheetsVerticesAtOnePointIsLeftWhole) {
  // One triangle's border runs from (2,0,0) to (0,0,0); two fins, above and below, each have a
  // vertex at (1,0,0) with their borders running back along it. Splitting the edge there would
  // have to choose between them: the split is tried, the stitch refuses it, and the mesh stays
  // as it was.
  const Soup triangle{{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}}, {{0, 1, 2}}};
  Mesh mesh = load(append(triangle, fins_along_x_axis({90, -90})));
  const Mesh before = mesh;
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.t_junctions, 0u);
  EXPECT_EQ(report.edges_stitched, 0u);
  EXPECT_TRUE(same_bits(face_corners(mesh), face_corners(before)));
  EXPECT_EQ(mesh.n_vertices(), before.n_vertices());
}

TEST_F(Stitch, RandomCutsOfRandomSurfacesAreAllZippedBackExactly) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 40; ++trial) {
    const Soup whole = trial % 2 ? sphere_soup(2) : terrain_soup(9);
    Soup cut = whole;
    std::uniform_real_distribution<double> unit(-1, 1);
    const Point normal = Point(unit(rng), unit(rng), unit(rng)).normalized();
    const double offset = 0.3 * unit(rng) + (trial % 2 ? 0.0 : 0.5);
    const double gap = trial % 3 == 0 ? 0.0 : 1e-7 * (1 + unit(rng));
    cut_apart(
        cut, [&](const Point& c) { return OpenMesh::dot(c, normal) > offset; }, gap, rng);
    Mesh mesh = load(cut);
    const std::size_t loops_before = find_holes(load(whole)).size();
    stitch_borders(mesh);
    EXPECT_EQ(find_holes(mesh).size(), loops_before) << "trial " << trial;
    EXPECT_TRUE(is_oriented_manifold(mesh)) << "trial " << trial;
    EXPECT_EQ(mesh.n_vertices(), whole.points.size()) << "trial " << trial;
    EXPECT_TRUE(same_bits(face_corners(mesh), face_corners(load(whole)))) << "trial " << trial;
  }
}

}  // namespace
}  // namespace holefill::testing
