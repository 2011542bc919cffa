// Pinched loops: a loop passing twice through one vertex is filled so that the vertex
// ends up with one fan of faces, whichever way the loop pairs the fans' sides there.
#include <fstream>
#include <numbers>

#include "dirty_meshes.h"
#include "fill_guarantees.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

struct Pinched {
  Mesh before, after;
  std::vector<Hole> holes;
  std::vector<HoleFill> fills;
};

Pinched fill_all(const Mesh& mesh) {
  Pinched p{mesh, mesh, find_holes(mesh), {}};
  p.fills = fill_holes(p.after, p.holes, FillOptions{});
  return p;
}

// Two bent fans of three triangles around the origin, touching only there: one loop runs
// around both, through the origin twice, each time from one fan's side to the other's.
Mesh bowtie_of_fans() {
  Mesh mesh;
  const auto centre = mesh.add_vertex(Point(0, 0, 0));
  for (const double start : {0.0, std::numbers::pi}) {
    std::vector<VertexHandle> rim;
    for (int i = 0; i < 4; ++i) {
      const double a = start + 0.25 * std::numbers::pi * i;
      rim.push_back(mesh.add_vertex(Point(std::cos(a), std::sin(a), 0.3 * std::sin(2 * a + 1))));
    }
    for (int i = 0; i < 3; ++i) mesh.add_face(centre, rim[i], rim[i + 1]);
  }
  return mesh;
}

TEST(PinchedLoops, ALoopThroughABowtieIsFilledAsTwoCornersAndTheVertexBecomesManifold) {
  const Mesh mesh = bowtie_of_fans();
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 1u);
  ASSERT_EQ(holes[0].repeated_vertices, 1u);
  ASSERT_FALSE(mesh.is_manifold(VertexHandle(0)));
  const Pinched p = fill_all(mesh);
  ASSERT_EQ(p.fills.size(), 1u);
  EXPECT_FALSE(p.fills[0].failed()) << p.fills[0].failure;
  EXPECT_EQ(check_fill_guarantees(p.before, p.holes, p.after, p.fills), "");
  EXPECT_TRUE(p.after.is_manifold(VertexHandle(0)));
  EXPECT_FALSE(p.after.is_boundary(VertexHandle(0)));  // its two gaps are both closed
  EXPECT_TRUE(find_holes(p.after).empty());
}

// A disk of 24 sectors and 3 rings around a centre (vertex 0), bowl-shaped, without the centre's
// triangles in sectors 0-2, 8-10 and 16-18: three gaps at the centre, between three fans.
constexpr int kSectors = 24;
Soup disk_with_three_gaps_at_its_centre() {
  Soup disk{{{0, 0, 0}}, {}};
  auto at = [](int ring, int sector) { return 1 + (ring - 1) * kSectors + sector % kSectors; };
  for (int ring = 1; ring <= 3; ++ring) {
    for (int s = 0; s < kSectors; ++s) {
      const double a = 2 * std::numbers::pi * s / kSectors;
      disk.points.emplace_back(ring * std::cos(a), ring * std::sin(a), 0.05 * ring * ring);
    }
  }
  for (int s = 0; s < kSectors; ++s) {
    if (s % 8 > 2) disk.faces.push_back({0, at(1, s), at(1, s + 1)});
    for (int ring = 1; ring < 3; ++ring) {
      disk.faces.push_back({at(ring, s), at(ring + 1, s), at(ring + 1, s + 1)});
      disk.faces.push_back({at(ring, s), at(ring + 1, s + 1), at(ring, s + 1)});
    }
  }
  return disk;
}

TEST(PinchedLoops, GapsBetweenThreeFansAreSeparatedIntoHolesOfTheirOwnAndEachIsFilledInItsGap) {
  const Soup soup = disk_with_three_gaps_at_its_centre();
  Mesh mesh = load_mesh_from_memory(obj_text(soup), "disk.obj");
  const std::vector<Hole> loaded = find_holes(mesh);
  // As built face by face, the three gaps come out as one loop through the centre three times.
  ASSERT_EQ(loaded.size(), 2u);
  ASSERT_EQ(loaded[0].size(), 24u);  // the rim
  ASSERT_EQ(loaded[1].repeated_vertices, 1u);
  EXPECT_EQ(separate_touching_holes(mesh, loaded), 2u);
  const std::vector<Hole> holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 4u);
  for (int id = 1; id <= 3; ++id) {
    const Hole& gap = holes[id];
    ASSERT_EQ(gap.size(), 5u);  // the centre and four points of the first ring
    EXPECT_EQ(gap.repeated_vertices, 0u);
    // All four ring points of one gap: sectors s0 .. s0 + 3 for s0 = 0, 8 or 16.
    int first_sector = kSectors;
    for (const auto v : gap.vertices) {
      if (v.idx() > 0) first_sector = std::min(first_sector, (v.idx() - 1) % kSectors);
    }
    EXPECT_EQ(first_sector % 8, 0);
    for (const auto v : gap.vertices) {
      if (v.idx() == 0) continue;
      EXPECT_LT(v.idx(), 1 + kSectors);  // on the first ring
      EXPECT_LE((v.idx() - 1) % kSectors - first_sector, 3);
    }
  }
  const Pinched p = fill_all(mesh);
  EXPECT_EQ(check_fill_guarantees(p.before, p.holes, p.after, p.fills), "");
  for (const auto& fill : p.fills) EXPECT_FALSE(fill.failed()) << fill.failure;
  EXPECT_TRUE(p.after.is_manifold(VertexHandle(0)));
  EXPECT_FALSE(p.after.is_boundary(VertexHandle(0)));
  // Every patch triangle lies in a gap (its centroid's angle about the centre within sectors
  // s0 .. s0 + 3): no patch reaches across a fan.
  for (const auto& fill : p.fills) {
    if (fill.patch.hole_id == 0) continue;  // the rim, closed too
    for (const auto f : fill.patch.faces) {
      const Point c = p.after.calc_face_centroid(f);
      const double sector = std::atan2(c[1], c[0]) / (2 * std::numbers::pi) * kSectors;
      const double in_gap = std::fmod(sector + kSectors, 8.0);
      EXPECT_GE(in_gap, 0.0);
      EXPECT_LE(in_gap, 3.0) << "sector " << sector;
    }
  }
}

TEST(PinchedLoops, ALoopAroundTheRimsOfABowtieIsNotSeparated) {
  Mesh mesh = bowtie_of_fans();
  const std::vector<Hole> holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_EQ(separate_touching_holes(mesh, holes), 0u);
  ASSERT_EQ(find_holes(mesh).size(), 1u);
  EXPECT_EQ(find_holes(mesh)[0].halfedges, holes[0].halfedges);
}

// A terrain with a square ring of cells removed around a square island of cells, the island
// tied to the rest by two cells on a diagonal that touch it and each other at corners only: one
// loop runs around the ring and passes twice through each of those corners.
Soup ring_with_pinches() {
  const int n = 21;
  const Soup grid =
      soup_of(make_grid(n, [](double u, double v) { return 0.1 * std::sin(3 * u + v); }));
  const double h = 1.0 / (n - 1);
  return without(grid, [h](const Point& c) {
    const int i = static_cast<int>(c[0] / h), j = static_cast<int>(c[1] / h);
    const bool ring =
        i >= 6 && i <= 13 && j >= 6 && j <= 13 && !(i >= 8 && i <= 11 && j >= 8 && j <= 11);
    const bool tie = (i == 7 && j == 7) || (i == 6 && j == 6);
    return ring && !tie;
  });
}

class PinchedFile : public ScratchTest {};

TEST_F(PinchedFile, ARingHoleTouchingItselfAtTwoCornersIsClosedAndTheCornersBecomeManifold) {
  const std::string input = write("ring.obj", obj_text(ring_with_pinches())).string();
  const Mesh mesh = load_mesh(input);
  const auto holes = find_holes(mesh);
  std::size_t repeated = 0;
  for (const auto& hole : holes) repeated += hole.repeated_vertices;
  ASSERT_EQ(repeated, 2u);
  const CliRun run = run_cli(
      {"fill", input, "-o", path("out.obj"), "--keep-borders", "--report", path("report.json")});
  EXPECT_EQ(run.code, cli::kOk) << run.err;
  const Mesh after = load_mesh(path("out.obj"));
  EXPECT_TRUE(is_oriented_manifold(after));
  EXPECT_TRUE(original_part_unchanged(mesh, after));
  EXPECT_EQ(find_holes(after).size(), 1u);  // the terrain's border, kept
  std::ifstream json(path("report.json"));
  const std::string report((std::istreambuf_iterator<char>(json)), {});
  EXPECT_NE(report.find("\"pinched_vertices\": "), std::string::npos) << report;
}

// find_separated_holes, walking again only the loops separation split, gives what find_holes gives
// after separate_touching_holes: the same loops in the same order, with the same ids, flags and
// measures; count_holes counts them.
TEST(PinchedLoops, SeparatedHolesAreWhatFindHolesGivesAfterTheSeparation) {
  const Mesh meshes[] = {
      load_mesh_from_memory(obj_text(disk_with_three_gaps_at_its_centre()), "disk.obj"),
      load_mesh_from_memory(obj_text(ring_with_pinches()), "ring.obj"), bowtie_of_fans()};
  std::size_t separated_loops = 0;
  for (const Mesh& mesh : meshes) {
    EXPECT_EQ(count_holes(mesh), find_holes(mesh).size());
    Mesh by_hand = mesh;
    separated_loops += separate_touching_holes(by_hand, find_holes(by_hand));
    const std::vector<Hole> expected = find_holes(by_hand);
    Mesh separated = mesh;
    const std::vector<Hole> holes = find_separated_holes(separated);
    EXPECT_EQ(count_holes(separated), expected.size());
    ASSERT_EQ(holes.size(), expected.size());
    for (std::size_t i = 0; i < holes.size(); ++i) {
      EXPECT_EQ(holes[i].id, expected[i].id);
      EXPECT_EQ(holes[i].halfedges, expected[i].halfedges);
      EXPECT_EQ(holes[i].vertices, expected[i].vertices);
      EXPECT_EQ(holes[i].pinched, expected[i].pinched);
      EXPECT_EQ(holes[i].repeated_vertices, expected[i].repeated_vertices);
      EXPECT_EQ(holes[i].perimeter, expected[i].perimeter);
      EXPECT_EQ(holes[i].centroid, expected[i].centroid);
      EXPECT_EQ(holes[i].mean_surrounding_edge_length, expected[i].mean_surrounding_edge_length);
    }
  }
  EXPECT_GE(separated_loops, 2u);  // the disk's gaps at least were separated
}

}  // namespace
}  // namespace holefill::testing
