// A cancel in each long phase that names itself (Progress::enter_phase): building the face index
// at a fill's start, refining between continued creases, factorising the fairing system. Each
// test cancels from the phase callback, so the cancel lands in that phase whatever the machine's
// speed: the work stops there, reports "cancelled", and the mesh is as it was.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "cad_parts.h"
#include "cancellable_ldlt.h"
#include "holefill/fair.h"
#include "holefill/fill.h"
#include "holefill/fill_sequence.h"
#include "holefill/holes.h"
#include "mesh_face_index.h"
#include "test_meshes.h"

namespace holefill {
namespace {

// A Progress that cancels as the work enters `phase`, and records the phases entered.
struct CancelInPhase {
  explicit CancelInPhase(std::string_view phase)
      : progress([](double) {},
                 [this, phase](std::string_view entered) {
                   entered_phases.emplace_back(entered);
                   if (entered == phase) progress.cancel();
                 }) {}
  std::vector<std::string> entered_phases;
  Progress progress;
};

std::vector<Point> vertex_positions(const Mesh& mesh) {
  std::vector<Point> points;
  for (const auto v : mesh.vertices()) points.push_back(mesh.point(v));
  return points;
}

// The unit cube, ten grid squares along each edge, with a hole across the edge y = z = 0.
Mesh cube_with_hole_across_an_edge() {
  const auto lines = testing::grid_lines({{0.1, 10}});
  const Mesh cube = testing::surface_of({lines, lines, lines, [](int, int, int) { return true; }});
  return testing::without_faces(
      cube, [](const Point& c) { return (c - Point(0.5, 0, 0)).norm() < 0.25; });
}

Mesh sphere_with_a_cap_off() {
  return testing::without_faces(testing::make_icosphere(3), [](const Point& c) {
    return (c - Point(0.0, 0.0, 1.0)).norm() < 0.6;
  });
}

TEST(CancelInPhase, IndexingFacesStopsFillHolesWithTheMeshUnchanged) {
  Mesh mesh = sphere_with_a_cap_off();
  const std::vector<Point> before = vertex_positions(mesh);
  const std::size_t faces = mesh.n_faces();
  CancelInPhase cancel(phase::kIndexingFaces);
  EXPECT_TRUE(fill_holes(mesh, find_holes(mesh), {}, {}, &cancel.progress).empty());
  EXPECT_EQ(cancel.entered_phases, std::vector<std::string>{std::string(phase::kIndexingFaces)});
  EXPECT_EQ(mesh.n_faces(), faces);
  EXPECT_EQ(vertex_positions(mesh), before);
  EXPECT_EQ(find_holes(mesh).size(), 1u);
}

// A single hole is filled in the mesh itself (fill_groups): a cancel in any of its stages leaves
// the mesh as it was, as when its patch was made apart from the mesh.
TEST(CancelInPhase, AnyStageStopsFillHolesOfOneHoleWithTheMeshUnchanged) {
  for (const auto phase :
       {phase::kTriangulating, phase::kRefining, phase::kSmoothing, phase::kChecking}) {
    Mesh mesh = sphere_with_a_cap_off();
    const std::vector<Point> before = vertex_positions(mesh);
    const std::size_t faces = mesh.n_faces();
    CancelInPhase cancel(phase);
    FillOptions options;
    options.triangulate.progress = &cancel.progress;
    EXPECT_TRUE(fill_holes(mesh, find_holes(mesh), options, {}, &cancel.progress).empty());
    EXPECT_NE(std::find(cancel.entered_phases.begin(), cancel.entered_phases.end(), phase),
              cancel.entered_phases.end());
    EXPECT_EQ(mesh.n_faces(), faces) << phase;
    EXPECT_EQ(vertex_positions(mesh), before) << phase;
    EXPECT_EQ(find_holes(mesh).size(), 1u) << phase;
  }
}

TEST(CancelInPhase, IndexingFacesFilesNoFaceOnceCancelled) {
  const Mesh mesh = sphere_with_a_cap_off();
  const std::vector<detail::Box> regions{
      detail::neighbourhood_of(mesh, find_holes(mesh).at(0).vertices)};
  CancelInPhase never("no such phase");
  EXPECT_GT(detail::MeshFaceIndex(mesh, regions, 1, &never.progress).filed_faces(), 0u);
  CancelInPhase cancel(phase::kIndexingFaces);
  EXPECT_EQ(detail::MeshFaceIndex(mesh, regions, 1, &cancel.progress).filed_faces(), 0u);
}

TEST(CancelInPhase, IndexingFacesFailsTheSequencesStepAndALaterStepFilesAgain) {
  Mesh mesh = sphere_with_a_cap_off();
  const Mesh before = mesh;
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 1u);
  const std::vector<const Hole*> loops{&holes[0]};
  FillSequence sequence(mesh, {loops});
  CancelInPhase cancel(phase::kIndexingFaces);
  FillOptions options;
  options.triangulate.progress = &cancel.progress;
  HoleFill cancelled;
  EXPECT_EQ(sequence.step(loops, cancelled, options), StageRun::Failed);
  EXPECT_EQ(cancelled.failure.kind, FailureKind::Cancelled) << cancelled.failure;
  EXPECT_EQ(cancelled.stage(), Stage::Original);
  EXPECT_EQ(mesh.n_faces(), before.n_faces());
  EXPECT_EQ(vertex_positions(mesh), vertex_positions(before));
  // Without the cancel the same sequence fills the hole as a sequence never cancelled does.
  HoleFill fill;
  while (sequence.step(loops, fill, {}) == StageRun::Ran) {
  }
  Mesh fresh = before;
  FillSequence fresh_sequence(fresh, {loops});
  HoleFill fresh_fill;
  while (fresh_sequence.step(loops, fresh_fill, {}) == StageRun::Ran) {
  }
  EXPECT_EQ(fill.stage(), Stage::Smoothed);
  EXPECT_EQ(vertex_positions(mesh), vertex_positions(fresh));
}

TEST(CancelInPhase, AFillSaysEachStageAndCheckAsItEntersIt) {
  Mesh mesh = sphere_with_a_cap_off();
  const auto holes = find_holes(mesh);
  const std::vector<const Hole*> loops{&holes.at(0)};
  FillSequence sequence(mesh, {loops});
  CancelInPhase never("no such phase");
  FillOptions options;
  options.triangulate.progress = &never.progress;
  HoleFill fill;
  while (sequence.step(loops, fill, options) == StageRun::Ran) {
  }
  ASSERT_EQ(fill.stage(), Stage::Smoothed);
  // Each stage's phase, then the check of what it made (the triangulation's are its own: it
  // steers clear of the mesh), after the index of the faces around.
  std::vector<std::string> stages;
  for (const auto& entered : never.entered_phases) {
    if (stages.empty() || stages.back() != entered) stages.push_back(entered);
  }
  const std::vector<std::string> expected{
      std::string(phase::kIndexingFaces), std::string(phase::kTriangulating),
      std::string(phase::kRefining),      std::string(phase::kChecking),
      std::string(phase::kSmoothing),     std::string(phase::kChecking)};
  EXPECT_EQ(stages, expected);
}

TEST(CancelInPhase, RefiningBetweenCreasesIsUndone) {
  Mesh mesh = cube_with_hole_across_an_edge();
  const Hole hole = find_holes(mesh).at(0);
  FillOptions options;
  options.features.angle_degrees = 40.0;
  HoleFill fill;
  ASSERT_EQ(advance(mesh, hole, fill, options), StageRun::Ran);
  ASSERT_EQ(fill.stage(), Stage::Triangulated);
  ASSERT_FALSE(fill.creases.empty());  // the refinement below is the one between creases
  const std::vector<Point> before = vertex_positions(mesh);
  const std::size_t faces = mesh.n_faces();
  CancelInPhase cancel(phase::kRefiningBetweenCreases);
  options.triangulate.progress = &cancel.progress;
  EXPECT_EQ(advance(mesh, hole, fill, options), StageRun::Failed);
  EXPECT_EQ(fill.failure.kind, FailureKind::Cancelled) << fill.failure;
  EXPECT_EQ(fill.stage(), Stage::Triangulated);
  EXPECT_EQ(mesh.n_faces(), faces);
  EXPECT_EQ(vertex_positions(mesh), before);
}

TEST(CancelInPhase, FactorisingStopsFairingWithTheMeshUnchanged) {
  Mesh mesh = sphere_with_a_cap_off();
  const Hole hole = find_holes(mesh).at(0);
  HoleFill fill;
  while (fill.stage() < Stage::Refined) ASSERT_EQ(advance(mesh, hole, fill, {}), StageRun::Ran);
  const std::vector<Point> before = vertex_positions(mesh);
  CancelInPhase cancel(phase::kFactorising);
  FillOptions options;
  options.smooth.method = SmoothMethod::Fair;
  options.smooth.fair.order = 3;
  options.triangulate.progress = &cancel.progress;
  EXPECT_EQ(advance(mesh, hole, fill, options), StageRun::Failed);
  EXPECT_EQ(fill.failure.kind, FailureKind::Cancelled) << fill.failure;
  // Stopped in the factorisation: the solve after it (phase::kSmoothing again) never started.
  const auto factorising = std::find(cancel.entered_phases.begin(), cancel.entered_phases.end(),
                                     std::string(phase::kFactorising));
  ASSERT_NE(factorising, cancel.entered_phases.end());
  EXPECT_EQ(std::find(factorising, cancel.entered_phases.end(), std::string(phase::kSmoothing)),
            cancel.entered_phases.end());
  EXPECT_EQ(vertex_positions(mesh), before);
  // Uncancelled, the same fairing enters the phase and moves the patch.
  CancelInPhase never("no such phase");
  const FairResult result = fair_patch(mesh, fill.patch, options.smooth.fair, &never.progress);
  EXPECT_TRUE(result.solved) << result.problem;
  EXPECT_EQ(never.entered_phases, (std::vector<std::string>{std::string(phase::kFactorising),
                                                            std::string(phase::kSmoothing)}));
  EXPECT_NE(vertex_positions(mesh), before);
}

using Sparse = Eigen::SparseMatrix<double>;

// The system fairing solves, on a grid: K (M^-1 K)^(order-1) with K a graph Laplacian of random
// positive edge weights plus the held border, M random masses, on the grid's inner vertices.
Sparse grid_fairing_system(int side, int order, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> weight(0.2, 2.0);
  const int n = side * side;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const int v = i * side + j;
      for (const int w : {i + 1 < side ? v + side : -1, j + 1 < side ? v + 1 : -1}) {
        if (w < 0) continue;
        const double x = weight(rng);
        entries.emplace_back(v, w, -x);
        entries.emplace_back(w, v, -x);
        diagonal[v] += x;
        diagonal[w] += x;
      }
    }
  }
  for (int v = 0; v < n; ++v) entries.emplace_back(v, v, diagonal[v]);
  Sparse stiffness(n, n);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd inverse_mass(n);
  for (int v = 0; v < n; ++v) inverse_mass[v] = weight(rng);
  Sparse system = stiffness;
  for (int power = 1; power < order; ++power) {
    system = Sparse(stiffness * inverse_mass.asDiagonal() * system);
  }
  std::vector<int> inner;
  for (int i = 1; i + 1 < side; ++i) {
    for (int j = 1; j + 1 < side; ++j) inner.push_back(i * side + j);
  }
  Sparse block(static_cast<int>(inner.size()), static_cast<int>(inner.size()));
  std::vector<Eigen::Triplet<double>> kept;
  std::vector<int> position(n, -1);
  for (std::size_t k = 0; k < inner.size(); ++k) position[inner[k]] = static_cast<int>(k);
  for (int c = 0; c < system.outerSize(); ++c) {
    for (Sparse::InnerIterator it(system, c); it; ++it) {
      const int r = position[static_cast<std::size_t>(it.row())];
      const int col = position[static_cast<std::size_t>(it.col())];
      if (r >= 0 && col >= 0) kept.emplace_back(r, col, it.value());
    }
  }
  block.setFromTriplets(kept.begin(), kept.end());
  return block;
}

bool same_matrix_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::equal(a.data(), a.data() + a.size(), b.data());
}

TEST(CancellableLdlt, FactorIsEigensBitForBit) {
  for (const int order : {1, 2, 3}) {
    const Sparse system = grid_fairing_system(24, order, 7u + static_cast<unsigned>(order));
    Eigen::SimplicialLDLT<Sparse> eigen;
    eigen.compute(system);
    ASSERT_EQ(eigen.info(), Eigen::Success);
    detail::CancellableLdlt ours;
    ours.analyzePattern(system);
    ASSERT_TRUE(ours.factorize_unless_cancelled(system, nullptr));
    ASSERT_EQ(ours.info(), Eigen::Success);
    EXPECT_TRUE(same_matrix_bits(Eigen::MatrixXd(ours.matrixL().nestedExpression()),
                                 Eigen::MatrixXd(eigen.matrixL().nestedExpression())));
    EXPECT_TRUE(same_matrix_bits(ours.vectorD(), eigen.vectorD()));
    const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(system.rows(), 3);
    EXPECT_TRUE(same_matrix_bits(ours.solve(rhs), eigen.solve(rhs)));
  }
}

TEST(CancellableLdlt, ASingularSystemIsReportedAsEigenReportsIt) {
  // A row and column of zeros: that row's pivot is exactly zero, wherever the ordering puts it.
  Sparse system = grid_fairing_system(6, 1, 3u);
  system.prune(
      [](Eigen::Index row, Eigen::Index column, double) { return row != 0 && column != 0; });
  Eigen::SimplicialLDLT<Sparse> eigen;
  eigen.compute(system);
  detail::CancellableLdlt ours;
  ours.analyzePattern(system);
  ASSERT_TRUE(ours.factorize_unless_cancelled(system, nullptr));
  EXPECT_EQ(eigen.info(), Eigen::NumericalIssue);
  EXPECT_EQ(ours.info(), eigen.info());
}

TEST(CancellableLdlt, ACancelStopsBeforeTheFirstRow) {
  const Sparse system = grid_fairing_system(10, 2, 5u);
  CancelInPhase cancel(phase::kFactorising);
  detail::CancellableLdlt ours;
  ours.analyzePattern(system);
  EXPECT_FALSE(ours.factorize_unless_cancelled(system, &cancel.progress));
  EXPECT_TRUE(cancel.progress.cancelled());
}

}  // namespace
}  // namespace holefill
