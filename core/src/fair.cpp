#include "holefill/fair.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <functional>
#include <numbers>
#include <unordered_map>
#include <vector>

#include "cancellable_ldlt.h"
#include "deletion_flags.h"

namespace holefill {
namespace {

// Cotangents are clamped to the cotangent of 1 degree: a sliver triangle must not give one edge
// a weight thousands of times its neighbours' (which ruins the conditioning), and a zero-area
// triangle must not give an infinite one.
const double kMaxCotangent = 1.0 / std::tan(std::numbers::pi / 180.0);
// A vertex whose area is below this fraction of the mean area is degenerate (M^-1 would blow up).
constexpr double kMinRelativeArea = 1e-12;
// Smallest to largest LDLT pivot below this: the system is numerically singular.
constexpr double kMinPivotRatio = 1e-14;
// Relative residual above this: the solve did not produce an answer worth keeping.
constexpr double kMaxRelativeResidual = 1e-6;

using SparseMatrix = Eigen::SparseMatrix<double>;

// The vertices the operator touches: the patch's own vertices (ring 0, the unknowns) first, then
// the rings around them up to `order` (the fixed ones), with their ring number.
struct Region {
  std::vector<VertexHandle> vertices;
  std::vector<int> ring;
  std::unordered_map<int, int> index;  // vertex idx -> position in `vertices`
  std::size_t unknowns = 0;
  // Fixed vertices at the edge of a restricted surface (a face of theirs is not on it): their
  // Laplacian would be one-sided, pulling the patch sideways, so they hold positions only.
  std::vector<bool> cut;
};

// The faces the operator may use (fair_patch_within); null: all.
using Surface = std::function<bool(FaceHandle)>;

// Whether the edge of halfedge h borders a face of the surface.
bool on_surface(const Mesh& mesh, HalfedgeHandle h, const Surface* surface) {
  return !surface || (*surface)(mesh.face_handle(h)) || (*surface)(mesh.opposite_face_handle(h));
}

Region gather_region(const Mesh& mesh, const std::vector<VertexHandle>& new_vertices, int order,
                     const Surface* surface) {
  Region region;
  auto add = [&](VertexHandle v, int ring) {
    if (region.index.emplace(v.idx(), static_cast<int>(region.vertices.size())).second) {
      region.vertices.push_back(v);
      region.ring.push_back(ring);
    }
  };
  for (const auto v : new_vertices) add(v, 0);
  region.unknowns = region.vertices.size();
  std::size_t ring_begin = 0;
  for (int ring = 1; ring <= order; ++ring) {
    const std::size_t ring_end = region.vertices.size();
    for (std::size_t i = ring_begin; i < ring_end; ++i) {
      if (!surface) {
        for (const auto w : mesh.vv_range(region.vertices[i])) add(w, ring);
        continue;
      }
      for (const auto h : mesh.voh_range(region.vertices[i])) {
        if (on_surface(mesh, h, surface)) add(mesh.to_vertex_handle(h), ring);
      }
    }
    ring_begin = ring_end;
  }
  region.cut.assign(region.vertices.size(), false);
  for (std::size_t i = region.unknowns; surface && i < region.vertices.size(); ++i) {
    for (const auto f : mesh.vf_range(region.vertices[i])) {
      if (!(*surface)(f)) region.cut[i] = true;
    }
  }
  return region;
}

// Cotangent of the angle at `corner` in the triangle (corner, a, b), clamped; 0 when the corner
// coincides with a or b (the angle is undefined, so it contributes nothing).
double clamped_cotangent(const Point& corner, const Point& a, const Point& b) {
  const Point u = a - corner, v = b - corner;
  const double sine = OpenMesh::cross(u, v).norm(), cosine = OpenMesh::dot(u, v);
  if (sine == 0.0 && cosine == 0.0) return 0.0;
  if (sine * kMaxCotangent <= std::abs(cosine))
    return cosine > 0.0 ? kMaxCotangent : -kMaxCotangent;
  return cosine / sine;
}

// Half the cotangent of the angle opposite halfedge h in its face; 0 on a boundary halfedge and
// off the surface.
double half_cotangent_opposite(const Mesh& mesh, HalfedgeHandle h, const Surface* surface) {
  if (mesh.is_boundary(h) || (surface && !(*surface)(mesh.face_handle(h)))) return 0.0;
  const Point& corner = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
  return 0.5 * clamped_cotangent(corner, mesh.point(mesh.from_vertex_handle(h)),
                                 mesh.point(mesh.to_vertex_handle(h)));
}

// The edge's cotangent weight (cot alpha + cot beta) / 2. It is negative on an edge that is not
// locally Delaunay and is kept so: clamping it to 0 would lose linear precision (a flat patch
// would slide within its plane), and K stays positive semi-definite without it, being the
// finite-element stiffness matrix of the piecewise-linear surface.
double cotangent_weight(const Mesh& mesh, HalfedgeHandle h, const Surface* surface) {
  return half_cotangent_opposite(mesh, h, surface) +
         half_cotangent_opposite(mesh, mesh.opposite_halfedge_handle(h), surface);
}

// The mixed Voronoi area of vertex p in triangle (p, q, r) (Meyer, Desbrun, Schroeder & Barr
// 2003): the Voronoi region when the triangle is not obtuse, otherwise a fixed share of its area,
// so it is never negative and the areas around a vertex sum to its share of the surface.
double mixed_area(const Point& p, const Point& q, const Point& r) {
  const double area = 0.5 * OpenMesh::cross(q - p, r - p).norm();
  if (!(area > 0.0)) return 0.0;
  const bool obtuse_p = OpenMesh::dot(q - p, r - p) < 0.0;
  const bool obtuse_q = OpenMesh::dot(p - q, r - q) < 0.0;
  const bool obtuse_r = OpenMesh::dot(p - r, q - r) < 0.0;
  if (obtuse_p) return 0.5 * area;
  if (obtuse_q || obtuse_r) return 0.25 * area;
  const double cot_q = OpenMesh::dot(p - q, r - q) / (2.0 * area);
  const double cot_r = OpenMesh::dot(p - r, q - r) / (2.0 * area);
  return ((r - p).sqrnorm() * cot_q + (q - p).sqrnorm() * cot_r) / 8.0;
}

double vertex_area(const Mesh& mesh, VertexHandle v, const Surface* surface) {
  double area = 0.0;
  for (const auto h : mesh.voh_range(v)) {
    if (mesh.is_boundary(h) || (surface && !(*surface)(mesh.face_handle(h)))) continue;
    area += mixed_area(mesh.point(v), mesh.point(mesh.to_vertex_handle(h)),
                       mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h))));
  }
  return area;
}

// The stiffness matrix K (positive semi-definite: K x = -sum w_ij (x_j - x_i)) on the rows of
// the vertices within order-1 rings of the patch (the rows Delta^k needs), and the inverse
// masses of those rows, normalised by their mean so that the entries stay near 1.
struct Operator {
  SparseMatrix stiffness;
  Eigen::VectorXd inverse_mass;
  std::string problem;
};

Operator build_operator(const Mesh& mesh, const Region& region, const FairOptions& options,
                        const Surface* surface) {
  Operator op;
  const int n = static_cast<int>(region.vertices.size());
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  std::vector<int> rows;
  for (int i = 0; i < n; ++i) {
    if (region.ring[i] >= options.order || region.cut[i]) continue;
    rows.push_back(i);
    const VertexHandle v = region.vertices[i];
    double diagonal = 0.0;
    for (const auto h : mesh.voh_range(v)) {
      if (!on_surface(mesh, h, surface)) continue;
      const double weight = options.cotangent_weights ? cotangent_weight(mesh, h, surface) : 1.0;
      entries.emplace_back(i, region.index.at(mesh.to_vertex_handle(h).idx()), -weight);
      diagonal += weight;
    }
    if (!(diagonal > 0.0)) {
      op.problem = "degenerate patch: vertex " + std::to_string(v.idx()) + " has no usable edge";
      return op;
    }
    entries.emplace_back(i, i, diagonal);
    mass[i] = options.cotangent_weights ? vertex_area(mesh, v, surface) : diagonal;
  }
  double mean_mass = 0.0;
  for (const int i : rows) mean_mass += mass[i];
  mean_mass /= static_cast<double>(rows.size());
  op.inverse_mass = Eigen::VectorXd::Zero(n);
  for (const int i : rows) {
    if (!(mass[i] > kMinRelativeArea * mean_mass)) {
      op.problem = "degenerate patch: vertex " + std::to_string(region.vertices[i].idx()) +
                   " has (nearly) zero area";
      return op;
    }
    op.inverse_mass[i] = mean_mass / mass[i];
  }
  op.stiffness.resize(n, n);
  op.stiffness.setFromTriplets(entries.begin(), entries.end());
  return op;
}

// Builds the operator on the mesh's current geometry and solves; on success writes the unknowns'
// new positions into the mesh. Returns the problem otherwise, the mesh unchanged.
std::string solve(Mesh& mesh, const Region& region, const FairOptions& options,
                  const Surface* surface, FairResult& result, const Progress* progress) {
  const int n = static_cast<int>(region.vertices.size());
  const int unknowns = static_cast<int>(region.unknowns), fixed = n - unknowns;
  Eigen::MatrixXd positions(n, 3);
  for (int i = 0; i < n; ++i) {
    const Point& p = mesh.point(region.vertices[i]);
    positions.row(i) << p[0], p[1], p[2];
  }
  if (!positions.allFinite()) return "non-finite vertex coordinates in or around the patch";

  const Operator op = build_operator(mesh, region, options, surface);
  if (!op.problem.empty()) return op.problem;
  if (is_cancelled(progress)) return kCancelledReason;
  // K (M^-1 K)^(k-1): symmetric positive definite on the unknowns' block.
  SparseMatrix system = op.stiffness;
  for (int power = 1; power < options.order; ++power) {
    system = SparseMatrix(op.stiffness * op.inverse_mass.asDiagonal() * system);
    if (is_cancelled(progress)) return kCancelledReason;
  }
  const SparseMatrix on_unknowns = system.block(0, 0, unknowns, unknowns);
  const SparseMatrix on_fixed = system.block(0, unknowns, unknowns, fixed);
  const Eigen::MatrixXd rhs = -(on_fixed * positions.bottomRows(fixed));

  if (is_cancelled(progress)) return kCancelledReason;  // before the ordering (0.6 s at 62K rows)
  detail::CancellableLdlt solver;
  solver.analyzePattern(on_unknowns);
  if (is_cancelled(progress)) return kCancelledReason;
  if (!solver.factorize_unless_cancelled(on_unknowns, progress)) return kCancelledReason;
  enter_phase(progress, phase::kSmoothing);  // the solve and the rest of the stage
  if (solver.info() != Eigen::Success) {
    return "the fairing system could not be factorised (singular or not positive)";
  }
  const Eigen::VectorXd pivots = solver.vectorD();
  const double smallest = pivots.minCoeff(), largest = pivots.cwiseAbs().maxCoeff();
  if (!(smallest > 0.0)) {
    return "the fairing system is singular (a patch vertex is not tied to the fixed ones)";
  }
  if (!(smallest > kMinPivotRatio * largest)) {
    return "the fairing system is ill-conditioned (pivot ratio " +
           std::to_string(smallest / largest) + ")";
  }
  const Eigen::MatrixXd solution = solver.solve(rhs);
  const double rhs_norm = rhs.norm();
  result.relative_residual =
      rhs_norm > 0.0 ? (on_unknowns * solution - rhs).norm() / rhs_norm : solution.norm();
  if (!solution.allFinite() || !(result.relative_residual <= kMaxRelativeResidual)) {
    return "the fairing solve is inaccurate (relative residual " +
           std::to_string(result.relative_residual) + ")";
  }
  for (int i = 0; i < unknowns; ++i) {
    mesh.set_point(region.vertices[i], Point(solution(i, 0), solution(i, 1), solution(i, 2)));
  }
  return {};
}

// fair_patch, on the faces of `surface` only (null: every face).
FairResult fair_on(Mesh& mesh, const Patch& patch, const FairOptions& options,
                   const Surface* surface, const Progress* progress) {
  FairResult result;
  if (options.order < 1 || options.order > 3) {
    result.problem = "fairing order must be 1, 2 or 3, got " + std::to_string(options.order);
    return result;
  }
  for (const auto v : patch.new_vertices) {
    if (!v.is_valid() || static_cast<std::size_t>(v.idx()) >= mesh.n_vertices() ||
        detail::is_deleted(mesh, v)) {
      result.problem = "the patch lists a vertex that is not in the mesh";
      return result;
    }
  }
  const Region region = gather_region(mesh, patch.new_vertices, options.order, surface);
  result.unknowns = region.unknowns;
  result.fixed_vertices = region.vertices.size() - region.unknowns;
  if (region.unknowns == 0) {
    result.solved = true;
    return result;
  }
  if (result.fixed_vertices == 0) {
    result.problem = "no fixed vertices around the patch to continue";
    return result;
  }
  result.problem = solve(mesh, region, options, surface, result, progress);
  result.solved = result.problem.empty();
  return result;
}

}  // namespace

FairResult fair_patch(Mesh& mesh, const Patch& patch, const FairOptions& options,
                      const Progress* progress) {
  return fair_on(mesh, patch, options, nullptr, progress);
}

FairResult fair_patch_within(Mesh& mesh, const Patch& patch, const FairOptions& options,
                             const std::function<bool(FaceHandle)>& surface,
                             const Progress* progress) {
  return fair_on(mesh, patch, options, &surface, progress);
}

}  // namespace holefill
