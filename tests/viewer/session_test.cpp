#include "session.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "holefill/io.h"
#include "test_sessions.h"

namespace holefill::viewer {
namespace {

TEST(Session, OpensTheBunnyWithItsThreeHolesLargestFirst) {
  Session session = bunny_session();
  ASSERT_EQ(session.holes().size(), 3u);
  EXPECT_EQ(session.holes()[0].size(), 99u);
  EXPECT_EQ(session.selected(), -1);
  EXPECT_FALSE(session.next_stage());
}

TEST(Session, MarksTheBorderOfAnOpenSurfaceAndNoLoopOfAClosedOne) {
  Session session;
  ASSERT_TRUE(session.open(std::filesystem::path(HOLEFILL_TEST_ASSETS) / "ragged_disk.obj"));
  ASSERT_EQ(session.holes().size(), 2u);
  EXPECT_TRUE(session.is_border(0));  // the height field's outer rim
  EXPECT_FALSE(session.is_border(1));
  session = bunny_session();
  for (const auto& hole : session.holes()) EXPECT_FALSE(session.is_border(hole.id));
}

TEST(Session, StitchesSeamsWhenItOpensAMesh) {
  // Two triangles of a square, each with its own copies of the diagonal's ends.
  const auto file = std::filesystem::temp_directory_path() / "holefill_session_seam.obj";
  {
    std::ofstream out(file);
    out << "v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 0 0\nv 1 1 0.5\nv 0 1 0\nf 1 2 3\nf 4 5 6\n";
  }
  Session session;
  ASSERT_TRUE(session.open(file)) << session.notice().text;
  std::filesystem::remove(file);
  EXPECT_EQ(session.mesh().n_vertices(), 4u);
  EXPECT_EQ(session.holes().size(), 1u);
  EXPECT_NE(session.notice().text.find("stitched 1 boundary edges"), std::string::npos)
      << session.notice().text;
}

TEST(Session, SaysThatRemoveSmallPiecesRemovesALoneTriangleAndOpensWithoutIt) {
  // A closed tetrahedron and a lone triangle beside it.
  const auto file = std::filesystem::temp_directory_path() / "holefill_session_pieces.obj";
  std::ofstream(file) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
                         "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\nf 5 6 7\n";
  Session session;
  ASSERT_TRUE(session.open(file)) << session.notice().text;
  const std::string told = session.notice().text;
  // The panel's button, not a flag of another program.
  EXPECT_NE(told.find("1 lone triangle beside the surface, of at most 1 face; \"Remove small "
                      "pieces\" removes them"),
            std::string::npos)
      << told;
  EXPECT_EQ(told.find("--"), std::string::npos) << told;
  EXPECT_EQ(session.pieces().lone_triangles, 1u);
  EXPECT_EQ(session.pieces().largest_small_piece, 1u);
  // What the button does: the file opened again without pieces of at most that many faces.
  ASSERT_TRUE(session.open(file, nullptr, session.pieces().largest_small_piece));
  std::filesystem::remove(file);
  EXPECT_EQ(session.mesh().n_faces(), 4u);
  EXPECT_EQ(session.pieces().lone_triangles + session.pieces().small_pieces, 0u);
  EXPECT_NE(session.notice().text.find("removed 1 pieces of at most 1 faces"), std::string::npos)
      << session.notice().text;
}

TEST(Session, StagesRunInOrderOnTheSelectedHole) {
  Session session = bunny_session();
  session.select(2);
  EXPECT_FALSE(session.can_step(Stage::Refined));
  EXPECT_FALSE(session.step(Stage::Smoothed));
  EXPECT_TRUE(session.can_step(Stage::Triangulated));
  ASSERT_TRUE(session.step(Stage::Triangulated));
  EXPECT_EQ(session.fill(2).stage(), Stage::Triangulated);
  EXPECT_FALSE(session.step(Stage::Triangulated));
  ASSERT_TRUE(session.step(Stage::Refined));
  ASSERT_TRUE(session.step(Stage::Smoothed));
  EXPECT_EQ(session.fill(2).stage(), Stage::Smoothed);
  EXPECT_FALSE(session.next_stage());
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
  EXPECT_EQ(session.holes().size(), 3u);  // holes keep their ids after a fill
}

TEST(Session, UndoAndRedoRestoreTheMeshExactly) {
  Session session = bunny_session();
  const Mesh loaded = session.mesh();
  session.select(0);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  const Mesh triangulated = session.mesh();
  ASSERT_TRUE(session.step(Stage::Refined));
  ASSERT_TRUE(session.step(Stage::Smoothed));
  const Mesh smoothed = session.mesh();
  session.select(1);
  ASSERT_TRUE(session.fill_selected());
  const Mesh both = session.mesh();

  ASSERT_TRUE(session.undo());
  EXPECT_TRUE(same_mesh(session.mesh(), smoothed));
  EXPECT_EQ(session.fill(1).stage(), Stage::Original);
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE(same_mesh(session.mesh(), triangulated));
  EXPECT_EQ(session.fill(0).stage(), Stage::Triangulated);
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE(same_mesh(session.mesh(), loaded));
  EXPECT_FALSE(session.undo());

  for (int i = 0; i < 4; ++i) ASSERT_TRUE(session.redo());
  EXPECT_TRUE(same_mesh(session.mesh(), both));
  EXPECT_FALSE(session.redo());
  EXPECT_EQ(session.selected(), 1);
}

TEST(Session, ANewStepAfterUndoDropsTheRedoHistory) {
  Session session = bunny_session();
  session.select(2);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE(session.can_redo());
  ASSERT_TRUE(session.fill_selected());
  EXPECT_FALSE(session.can_redo());
}

TEST(Session, FailedOpenKeepsThePreviousMeshAndSaysWhy) {
  Session session = bunny_session();
  session.select(1);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  const Mesh before = session.mesh();
  EXPECT_FALSE(session.open("/nonexistent/holefill/missing.obj"));
  EXPECT_TRUE(session.notice().error);
  EXPECT_NE(session.notice().text.find("missing.obj"), std::string::npos);
  EXPECT_TRUE(same_mesh(session.mesh(), before));
  EXPECT_EQ(session.selected(), 1);
  EXPECT_EQ(session.fill(1).stage(), Stage::Triangulated);
  EXPECT_TRUE(session.can_undo());
}

TEST(Session, ResetHoleTakesItsPatchOutAndKeepsOthers) {
  Session session = bunny_session();
  const Mesh loaded = session.mesh();
  session.select(2);
  ASSERT_TRUE(session.fill_selected());
  const Mesh only_two = session.mesh();
  session.select(0);
  ASSERT_TRUE(session.fill_selected());
  ASSERT_TRUE(session.reset_selected());
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
  EXPECT_TRUE(same_mesh(session.mesh(), only_two));
  session.select(2);
  ASSERT_TRUE(session.reset_selected());
  EXPECT_TRUE(same_mesh(session.mesh(), loaded));
}

TEST(Session, ChangingOptionsRerunsTheSelectedHolesStages) {
  Session session = bunny_session();
  session.select(0);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  ASSERT_TRUE(session.step(Stage::Refined));
  const std::size_t dense = session.fill(0).stats.new_vertices;
  FillOptions options = session.options();
  options.refine.tau = 1.0;
  session.set_options(options);
  EXPECT_EQ(session.fill(0).stage(), Stage::Refined);
  EXPECT_LT(session.fill(0).stats.new_vertices, dense);
  // One undo takes back the whole parameter change.
  options.refine.tau = 1.2;
  session.set_options(options);
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.fill(0).stats.new_vertices, dense);
  EXPECT_NEAR(session.options().refine.tau, std::sqrt(2.0), 1e-12);
}

TEST(Session, TurningRemeshOnRerunsTheRefinementWithMoreRegularVertices) {
  Session session = bunny_session();
  session.select(0);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  ASSERT_TRUE(session.step(Stage::Refined));
  auto regular = [&] {
    const auto& histogram = session.fill(0).stats.valence_histogram;
    const auto six = histogram.find(6);
    return six == histogram.end() ? std::size_t{0} : six->second;
  };
  const std::size_t regular_without = regular();
  FillOptions options = session.options();
  options.refine.remesh = true;
  session.set_options(options);
  EXPECT_EQ(session.fill(0).stage(), Stage::Refined);
  EXPECT_GT(session.fill(0).refinement.remeshing.flips, 0u);
  EXPECT_GT(regular(), regular_without);
  ASSERT_TRUE(session.undo());
  EXPECT_FALSE(session.options().refine.remesh);
  EXPECT_EQ(regular(), regular_without);
}

TEST(Session, FillAllFillsEveryHoleAndUndoesAsOneAction) {
  Session session = bunny_session();
  ASSERT_TRUE(session.fill_all());
  for (const auto& hole : session.holes()) {
    EXPECT_EQ(session.fill(hole.id).stage(), Stage::Smoothed);
  }
  ASSERT_TRUE(session.undo());
  for (const auto& hole : session.holes()) {
    EXPECT_EQ(session.fill(hole.id).stage(), Stage::Original);
  }
}

TEST(Session, MeshValencesCountEveryVertex) {
  Session session = bunny_session();
  std::size_t total = 0;
  for (const auto& [valence, count] : session.mesh_valences()) total += count;
  EXPECT_EQ(total, session.mesh().n_vertices());
}

TEST(Session, ComparisonFillsTheSelectedHoleWithEachWeight) {
  Session session = bunny_session();
  EXPECT_EQ(session.comparison(), nullptr);
  session.set_compare(true);
  EXPECT_EQ(session.comparison(), nullptr);  // nothing selected
  session.select(0);
  session.set_compare_triangulation_only(true);
  const Comparison* comparison = session.comparison();
  ASSERT_NE(comparison, nullptr);
  EXPECT_EQ(comparison->left.label, "liepa");
  EXPECT_EQ(comparison->right.label, "maxmin");
  EXPECT_EQ(comparison->left.fill.stage(), Stage::Triangulated);
  EXPECT_EQ(comparison->right.fill.stage(), Stage::Triangulated);
  // maxmin maximises the smallest angle, so it cannot do worse than liepa there, and on the
  // bunny's large hole the two triangulations differ.
  EXPECT_GE(comparison->right.fill.stats.min_angle_deg, comparison->left.fill.stats.min_angle_deg);
  EXPECT_NE(comparison->right.fill.stats.max_dihedral_deg,
            comparison->left.fill.stats.max_dihedral_deg);
  // The session's own mesh is untouched by the comparison.
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
}

// Umbrella against fair: the same triangulation and refinement on both sides (same weight, same
// tau), so the same patch connectivity, with the new vertices placed differently; the comparison
// follows the mode switch and leaves the session's mesh alone.
TEST(Session, ComparisonOfSmoothingFillsBothSidesAlikeButForTheSmoothing) {
  Session session = bunny_session();
  session.select(0);
  session.set_compare(true);
  session.set_compare_triangulation_only(true);  // ignored: smoothing is what differs
  const auto weights_version = (session.comparison(), session.comparison_version());
  session.set_compare_mode(CompareMode::Smoothing);
  const Comparison* comparison = session.comparison();
  ASSERT_NE(comparison, nullptr);
  EXPECT_GT(session.comparison_version(), weights_version);
  EXPECT_EQ(comparison->left.label, "umbrella");
  EXPECT_EQ(comparison->right.label, "fair");
  const HoleFill &umbrella = comparison->left.fill, &fair = comparison->right.fill;
  ASSERT_FALSE(umbrella.failed() || fair.failed());
  EXPECT_EQ(umbrella.stage(), Stage::Smoothed);
  EXPECT_EQ(fair.stage(), Stage::Smoothed);
  ASSERT_EQ(umbrella.patch.new_vertices.size(), fair.patch.new_vertices.size());
  ASSERT_GT(umbrella.patch.new_vertices.size(), 0u);
  EXPECT_EQ(comparison->left.mesh.n_faces(), comparison->right.mesh.n_faces());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < umbrella.patch.new_vertices.size(); ++i) {
    moved += comparison->left.mesh.point(umbrella.patch.new_vertices[i]) !=
             comparison->right.mesh.point(fair.patch.new_vertices[i]);
  }
  EXPECT_EQ(moved, umbrella.patch.new_vertices.size());
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
}

TEST(Session, ComparisonStartsFromTheHoleBeforeItsOwnSteps) {
  Session session = bunny_session();
  session.select(0);
  ASSERT_TRUE(session.fill_selected());
  session.set_compare(true);
  const Comparison* comparison = session.comparison();
  ASSERT_NE(comparison, nullptr);
  EXPECT_EQ(comparison->right.fill.stage(), Stage::Smoothed);
  EXPECT_FALSE(comparison->right.fill.failed());
  EXPECT_EQ(comparison->right.fill.stats.new_faces, session.fill(0).stats.new_faces);
}

TEST(Session, FillAllLeavesOpenABorderEveryCapOfWhichCutsTheSurfaceAsTheCliDoes) {
  const auto file = std::filesystem::path(HOLEFILL_TEST_ASSETS) / "ragged_disk.obj";
  Session session;
  ASSERT_TRUE(session.open(file));
  ASSERT_TRUE(session.is_border(0));
  EXPECT_FALSE(session.fill_all());  // the border is tried, and refused
  EXPECT_TRUE(session.fill(0).failed());
  EXPECT_EQ(session.fill(0).failure.kind, FailureKind::IntersectsMesh) << session.fill(0).failure;
  EXPECT_EQ(session.fill(1).stage(), Stage::Smoothed);
  EXPECT_NE(session.notice().text.find("1 refused"), std::string::npos) << session.notice().text;
  EXPECT_FALSE(session.fill_all_request());
  {  // the panel's "keep cutting patches" on the selected border: its best patch, counted
    Session keeping;
    ASSERT_TRUE(keeping.open(file));
    keeping.select(0);
    FillOptions keep = keeping.options();
    keep.allow_intersections = true;
    keeping.set_options(keep);
    ASSERT_TRUE(keeping.fill_selected());
    EXPECT_FALSE(keeping.fill(0).failed()) << keeping.fill(0).failure;
    EXPECT_GT(keeping.fill(0).self_intersections, 0u);
    EXPECT_EQ(keeping.fill(0).stage(), Stage::Smoothed);
  }
  {  // ticked after the refusal: the fill is run again to its end with the option
    Session ticked;
    ASSERT_TRUE(ticked.open(file));
    ticked.select(0);
    EXPECT_FALSE(ticked.fill_selected());
    ASSERT_TRUE(ticked.fill(0).failed());
    FillOptions keep = ticked.options();
    keep.allow_intersections = true;
    ticked.set_options(keep);
    EXPECT_FALSE(ticked.fill(0).failed()) << ticked.fill(0).failure;
    EXPECT_EQ(ticked.fill(0).stage(), Stage::Smoothed);
    EXPECT_GT(ticked.fill(0).self_intersections, 0u);
  }
  // The command-line tool writes the same mesh.
  Mesh cli = load_mesh(file);
  const PreparedMesh prepared = prepare_mesh(cli);
  fill_holes(cli, prepared.holes, {}, HoleSelection{prepared.ids_to_fill, 0});
  ASSERT_EQ(cli.n_faces(), session.mesh().n_faces());
  ASSERT_EQ(cli.n_vertices(), session.mesh().n_vertices());
  for (const auto v : cli.vertices()) {
    ASSERT_EQ(cli.point(v), session.mesh().point(v)) << v.idx();
  }
}

TEST(Session, SavesTheFilledMesh) {
  Session session = bunny_session();
  ASSERT_TRUE(session.fill_all());
  const auto path = std::filesystem::temp_directory_path() / "holefill_viewer_session_test.obj";
  ASSERT_TRUE(session.save(path)) << session.notice().text;
  Session reopened;
  ASSERT_TRUE(reopened.open(path));
  EXPECT_TRUE(reopened.holes().empty());
  std::filesystem::remove(path);
}

// An octahedron without two faces at its top, whose two fans there have a vertex each at the top's
// position: two holes touching at a vertex, as an exporter that splits vertices writes them.
TEST(Session, SavesTheFileVerticesWhereAWeldsHolesStayedOpen) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto input = dir / "holefill_viewer_touching.obj";
  std::ofstream(input) << "v 0 0 1\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\nv 0 0 1\n"
                          "f 1 3 4\nf 7 5 2\nf 6 3 2\nf 6 4 3\nf 6 5 4\nf 6 2 5\n";
  const auto output = dir / "holefill_viewer_touching_out.obj";
  for (const bool fill : {false, true}) {
    Session session;
    ASSERT_TRUE(session.open(input)) << session.notice().text;
    ASSERT_EQ(session.holes().size(), 2u);  // welded: two triangles touching at the top
    if (fill) {
      ASSERT_TRUE(session.fill_all());
    }
    ASSERT_TRUE(session.save(output)) << session.notice().text;
    const Mesh saved = load_mesh(output);
    // Left open, the holes get the file's two top vertices back; filled, one vertex joins them.
    EXPECT_EQ(saved.n_vertices(), fill ? 6u : 7u);
    EXPECT_EQ(session.notice().text.find("split 1 vertex") != std::string::npos, !fill);
    for (const auto v : saved.vertices()) EXPECT_TRUE(saved.is_manifold(v)) << v.idx();
  }
  std::filesystem::remove(input);
  std::filesystem::remove(output);
}

}  // namespace
}  // namespace holefill::viewer
