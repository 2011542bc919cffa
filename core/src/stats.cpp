#include "holefill/stats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "geometry.h"
#include "holefill/triangulate.h"
#include "parallel_indices.h"
#include "safe_scale.h"
#include "sets_by_lowest.h"

namespace holefill {
namespace {
constexpr double kDegrees = 180.0 / std::numbers::pi;

// The power of two the patch's points are divided by when measured: 0, or where its largest
// coordinate lies beyond safe_scale.h's range, that coordinate's exponent. Squared lengths
// overflow beyond about 1e77 (the fill is scaled, but its stats are measured at the mesh's own
// scale: at 1e78 every normal was zero and the angles read 90 and 180 degrees) and underflow
// below about 1e-77; the angles do not depend on the scale.
int measuring_exponent(double largest) {
  return detail::SafeScale::leaves_alone(largest) ? 0 : std::ilogb(largest);
}

Point scaled_down(const Point& p, int exponent) {
  if (exponent == 0) return p;
  return Point(std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent),
               std::ldexp(p[2], -exponent));
}

// The face's unit normal, from its points scaled down by 2^exponent where that is not 0.
Point face_normal(const Mesh& mesh, FaceHandle f, int exponent) {
  if (exponent == 0) return mesh.calc_face_normal(f);
  auto fv = mesh.cfv_iter(f);
  const Point a = scaled_down(mesh.point(*fv), exponent);
  const Point b = scaled_down(mesh.point(*++fv), exponent);
  const Point c = scaled_down(mesh.point(*++fv), exponent);
  const Point n = OpenMesh::cross(c - b, a - b);
  const double length = n.norm();
  return length > 0.0 ? n / length : n;
}

// Faces (or vertices) measured by one task when a patch is measured on several threads.
constexpr std::size_t kMeasuredPerBlock = 4096;

template <class Measure>
void measure_in_blocks(std::size_t count, unsigned threads, Measure&& measure) {
  detail::for_each_block(count, kMeasuredPerBlock, threads, std::forward<Measure>(measure));
}

// Where each patch face lies in patch.faces (-1: not the patch's), by face index from the
// patch's oldest face on (patch faces are among the newest of the mesh).
class FacePositions {
 public:
  explicit FacePositions(const Patch& patch) {
    for (const auto f : patch.faces) first_ = std::min(first_, f.idx());
    for (std::size_t p = 0; p < patch.faces.size(); ++p) {
      const auto slot = static_cast<std::size_t>(patch.faces[p].idx() - first_);
      if (slot >= position_.size()) position_.resize(slot + 1, -1);
      position_[slot] = static_cast<int>(p);
    }
  }
  int operator()(FaceHandle f) const {
    const auto slot = static_cast<std::size_t>(f.idx()) - static_cast<std::size_t>(first_);
    return f.is_valid() && f.idx() >= first_ && slot < position_.size() ? position_[slot] : -1;
  }

 private:
  int first_ = std::numeric_limits<int>::max();
  std::vector<int> position_;
};

// The largest angle between the normals of two faces across an edge of a patch face (boundary
// edges of the mesh left out): each edge once, from the patch face first in patch.faces when
// both are the patch's. `normals` holds the patch faces' normals, in patch.faces' order.
double largest_dihedral_angle(const Mesh& mesh, const Patch& patch,
                              const std::vector<Point>& normals, int exponent, unsigned threads) {
  const FacePositions position(patch);
  std::vector<double> block_max((patch.faces.size() + kMeasuredPerBlock - 1) / kMeasuredPerBlock,
                                0.0);
  measure_in_blocks(
      patch.faces.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t b) {
        for (std::size_t p = begin; p < end; ++p) {
          for (const auto h : mesh.fh_range(patch.faces[p])) {
            const FaceHandle other = mesh.opposite_face_handle(h);
            if (!other.is_valid()) continue;
            const int q = position(other);
            if (q >= 0 && static_cast<std::size_t>(q) < p) continue;  // measured from there
            const Point across =
                q >= 0 ? normals[static_cast<std::size_t>(q)] : face_normal(mesh, other, exponent);
            // The edge's first halfedge's face first, as a walk over the edges takes them (the same
            // bits whatever the compiler contracts).
            const bool first = h == mesh.halfedge_handle(mesh.edge_handle(h), 0);
            block_max[b] = std::max(block_max[b],
                                    geometry::angle_between_normals(first ? normals[p] : across,
                                                                    first ? across : normals[p]));
          }
        }
      });
  double largest = 0.0;
  for (const double value : block_max) largest = std::max(largest, value);
  return largest;
}

}  // namespace

PatchStats patch_stats(const Mesh& mesh, const Patch& patch) { return patch_stats(mesh, patch, 1); }

// Each face's and vertex's measures are taken in blocks on the threads, then added up in the
// patch's order, so that the sums are the same on any number of threads (the largest and
// smallest values do not depend on the order: std::max and std::min drop a NaN either way).
PatchStats patch_stats(const Mesh& mesh, const Patch& patch, unsigned threads) {
  PatchStats stats;
  stats.new_vertices = patch.new_vertices.size();
  stats.new_faces = patch.faces.size();
  const std::size_t faces = patch.faces.size();
  std::vector<int> valences(patch.new_vertices.size());
  measure_in_blocks(valences.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t i = begin; i < end; ++i) {
      valences[i] = static_cast<int>(mesh.valence(patch.new_vertices[i]));
    }
  });
  for (const int valence : valences) ++stats.valence_histogram[valence];

  std::vector<double> block_largest((faces + kMeasuredPerBlock - 1) / kMeasuredPerBlock, 0.0);
  measure_in_blocks(faces, threads, [&](std::size_t begin, std::size_t end, std::size_t b) {
    for (std::size_t p = begin; p < end; ++p) {
      for (const auto v : mesh.fv_range(patch.faces[p])) {
        block_largest[b] =
            std::max(block_largest[b], detail::SafeScale::largest_coordinate(mesh.point(v)));
      }
    }
  });
  double largest = 0.0;
  for (const double value : block_largest) largest = std::max(largest, value);
  const int exponent = measuring_exponent(largest);

  std::vector<double> min_angles(faces), areas(faces);
  std::vector<Point> normals(faces);
  measure_in_blocks(faces, threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t p = begin; p < end; ++p) {
      auto fv = mesh.cfv_iter(patch.faces[p]);
      const Point a = scaled_down(mesh.point(*fv), exponent);
      const Point b = scaled_down(mesh.point(*++fv), exponent);
      const Point c = scaled_down(mesh.point(*++fv), exponent);
      const geometry::TriangleMeasures m = geometry::measure_triangle(a, b, c);
      min_angles[p] = m.min_angle;
      areas[p] = m.area;
      normals[p] = face_normal(mesh, patch.faces[p], exponent);
    }
  });
  double min_angle = faces == 0 ? 0.0 : std::numbers::pi, angle_sum = 0.0;
  for (std::size_t p = 0; p < faces; ++p) {
    min_angle = std::min(min_angle, min_angles[p]);
    angle_sum += min_angles[p];
    stats.area += std::ldexp(areas[p], 2 * exponent);
  }
  stats.min_angle_deg = min_angle * kDegrees;
  stats.mean_min_angle_deg = faces == 0 ? 0.0 : angle_sum / static_cast<double>(faces) * kDegrees;
  stats.max_dihedral_deg =
      largest_dihedral_angle(mesh, patch, normals, exponent, threads) * kDegrees;
  return stats;
}

std::map<int, std::size_t> valence_histogram(const Mesh& mesh) {
  std::map<int, std::size_t> histogram;
  for (const auto v : mesh.vertices()) ++histogram[mesh.valence(v)];
  return histogram;
}

std::vector<int> component_labels(const Mesh& mesh) {
  std::vector<int> label(mesh.n_vertices(), -1);
  for (const auto v : mesh.vertices()) label[v.idx()] = v.idx();
  detail::number_sets_by_lowest(label, [&mesh](auto join) {
    for (const auto e : mesh.edges()) {
      const HalfedgeHandle h = mesh.halfedge_handle(e, 0);
      join(mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx());
    }
  });
  return label;
}

std::size_t connected_components(const Mesh& mesh) {
  const std::vector<int> label = component_labels(mesh);
  return label.empty()
             ? 0
             : static_cast<std::size_t>(*std::max_element(label.begin(), label.end()) + 1);
}

SurfaceCounts surface_counts(const Mesh& mesh) {
  const std::vector<int> label = component_labels(mesh);
  // Labels are numbered in order of first vertex, so a label seen for the first time is the
  // largest so far: count the labels of used vertices that exceed every earlier one.
  SurfaceCounts counts;
  int highest_used = -1;
  for (const auto v : mesh.vertices()) {
    if (mesh.is_isolated(v)) {
      ++counts.unused_vertices;
    } else if (label[v.idx()] > highest_used) {
      highest_used = label[v.idx()];
      ++counts.components;
    }
  }
  return counts;
}

}  // namespace holefill
