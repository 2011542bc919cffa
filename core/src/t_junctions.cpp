#include "t_junctions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "holefill/obj_attributes.h"
#include "parallel_indices.h"

namespace holefill::detail {
namespace {

// Where p projects onto the line a->b (0 at a, 1 at b) and how far it lies from that line.
struct Projection {
  double along = 0.0;
  double distance = INFINITY;
};
Projection project(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length2 = ab.sqrnorm();
  if (!(length2 > 0.0)) return {};
  const double along = OpenMesh::dot(p - a, ab) / length2;
  return {along, (p - (a + ab * along)).norm()};
}

// Whether v's own boundary runs back along a->b: a boundary neighbour of v lies on the line
// through a and b, before v (towards a) if v's boundary leaves v for it, after v if it comes from
// there. The two sides of a crack run in opposite directions, so this is what a crack looks like.
bool runs_back_along(const Mesh& mesh, VertexHandle v, double along_v, const Point& a,
                     const Point& b, double tolerance) {
  for (const auto out : mesh.voh_range(v)) {
    if (mesh.is_boundary(out)) {  // v -> next on v's loop
      const Projection next = project(mesh.point(mesh.to_vertex_handle(out)), a, b);
      if (next.distance <= tolerance && next.along < along_v) return true;
    }
    const HalfedgeHandle in = mesh.opposite_halfedge_handle(out);
    if (mesh.is_boundary(in)) {  // previous on v's loop -> v
      const Projection previous = project(mesh.point(mesh.from_vertex_handle(in)), a, b);
      if (previous.distance <= tolerance && previous.along > along_v) return true;
    }
  }
  return false;
}

// The OBJ corner values (texture coordinate and normal numbers) of a face corner.
struct CornerValues {
  int texcoord = 0, normal = 0;
};

// Appends the value a fraction `along` of the way from number `from` to number `to` to `table`
// and returns its number; 0 (none) when either end has none, the same number when both share it.
template <class Value, class Mix>
int interpolated(std::vector<Value>& table, int from, int to, double along, Mix&& mix) {
  if (from <= 0 || to <= 0) return 0;
  if (from == to) return from;
  table.push_back(mix(table[from - 1], table[to - 1], along));
  return static_cast<int>(table.size());
}

// Gives every corner of the faces around `fresh` (the new vertices on edge a->b, where `along`
// says) its OBJ values: those of the split face's corner at the same vertex, interpolated along
// the edge at the new vertices.
void set_split_corners(Mesh& mesh, const ObjHandles& obj, VertexHandle a, VertexHandle b,
                       const std::vector<std::pair<VertexHandle, double>>& fresh,
                       const std::vector<std::pair<VertexHandle, CornerValues>>& old_corners) {
  ObjTables& tables = mesh.property(obj.tables);
  CornerValues at_a, at_b;
  for (const auto& [vertex, values] : old_corners) {
    if (vertex == a) at_a = values;
    if (vertex == b) at_b = values;
  }
  std::vector<std::pair<VertexHandle, CornerValues>> corners = old_corners;
  for (const auto& [vertex, along] : fresh) {
    CornerValues values;
    values.texcoord = interpolated(tables.texcoords, at_a.texcoord, at_b.texcoord, along,
                                   [](const auto& p, const auto& q, double t) {
                                     return std::array<double, 3>{p[0] + t * (q[0] - p[0]),
                                                                  p[1] + t * (q[1] - p[1]),
                                                                  p[2] + t * (q[2] - p[2])};
                                   });
    values.normal = interpolated(tables.normals, at_a.normal, at_b.normal, along,
                                 [](const Point& p, const Point& q, double t) {
                                   const Point mixed = p + (q - p) * t;
                                   const double length = mixed.norm();
                                   return length > 0.0 ? mixed / length : mixed;
                                 });
    corners.emplace_back(vertex, values);
  }
  for (const auto& [vertex, along] : fresh) {
    for (const auto h : mesh.vih_range(vertex)) {
      if (mesh.is_boundary(h)) continue;
      for (const auto corner : mesh.fh_range(mesh.face_handle(h))) {
        for (const auto& [at, values] : corners) {
          if (at != mesh.to_vertex_handle(corner)) continue;
          mesh.property(obj.texcoord, corner) = values.texcoord;
          mesh.property(obj.normal, corner) = values.normal;
        }
      }
    }
  }
}

// A ball around a stretch of an edge holding more boundary points than this is halved: the
// ball around a long edge across a dense boundary holds points far from the edge, and looking at
// each of them made the search quadratic (100,000 stacked slivers, each base's ball holding half
// of all the apexes: over 300 s).
constexpr std::size_t kPointsPerStretch = 32;
// Stretches are halved at most this many times (a stretch of 2^-40 of the edge, or two
// tolerances, is as short as a search needs).
constexpr int kMostHalvings = 40;

// A nanoflann result set: appends the points within a squared radius to `found`, at most `cap` + 1
// of them (the search stops at the one over the cap).
class FirstPointsWithin {
 public:
  FirstPointsWithin(double squared_radius, std::size_t cap, std::vector<std::size_t>& found)
      : squared_radius_(squared_radius), cap_(cap), found_(found) {}
  double worstDist() const { return squared_radius_; }
  bool full() const { return true; }
  bool addPoint(double squared, std::size_t index) {
    if (squared < squared_radius_) {
      found_.push_back(index);
      ++count_;
    }
    return count_ <= cap_;
  }

 private:
  double squared_radius_;
  std::size_t cap_;
  std::vector<std::size_t>& found_;
  std::size_t count_ = 0;
};

// Appends to `near` the boundary points within `tolerance` of segment a-b (and maybe some more):
// those in the ball around it, or, when it holds more than kPointsPerStretch, those near each
// half. The work grows with the points near the segment, not with those in its ball.
void points_near_segment(const BoundaryPointTree& tree, const Point& a, const Point& b,
                         double tolerance, std::vector<std::size_t>& near, int halvings = 0) {
  const double half = 0.5 * (b - a).norm();
  const bool may_halve = half > 2.0 * tolerance && halvings < kMostHalvings;
  const std::size_t before = near.size();
  const double radius = half + tolerance;
  FirstPointsWithin within(std::nextafter(radius * radius, INFINITY),
                           may_halve ? kPointsPerStretch : SIZE_MAX, near);
  const Point centre = (a + b) * 0.5;
  tree.findNeighbors(within, centre.data(), nanoflann::SearchParams(32, 0.0f, false));
  if (near.size() - before <= kPointsPerStretch || !may_halve) return;
  near.resize(before);
  points_near_segment(tree, a, centre, tolerance, near, halvings + 1);
  points_near_segment(tree, centre, b, tolerance, near, halvings + 1);
}

}  // namespace

std::vector<TJunction> find_t_junctions(const Mesh& mesh, const BoundaryIndex& index,
                                        double tolerance, const std::vector<int>& with_partner,
                                        unsigned threads) {
  const BoundaryPoints& points = index.points;
  const BoundaryPointTree& tree = index.tree;
  if (points.vertices.empty()) return {};
  // The halfedges in blocks on `threads` threads, each block's junctions in its halfedges' order,
  // the blocks then joined in order: the junctions of one thread (this search was a third of
  // stitching 20,000 holes' borders, all of it on the caller).
  constexpr std::size_t kHalfedgesPerBlock = std::size_t{1} << 14;
  std::vector<std::vector<TJunction>> block_junctions(
      (mesh.n_halfedges() + kHalfedgesPerBlock - 1) / kHalfedgesPerBlock);
  for_each_block(
      mesh.n_halfedges(), kHalfedgesPerBlock, threads,
      [&](std::size_t begin, std::size_t end, std::size_t block) {
        std::vector<TJunction>& junctions = block_junctions[block];
        std::vector<std::size_t> found;
        for (std::size_t i = begin; i < end; ++i) {
          const HalfedgeHandle h(static_cast<int>(i));
          if (!mesh.is_boundary(h)) continue;
          const VertexHandle from = mesh.from_vertex_handle(h), to = mesh.to_vertex_handle(h);
          const Point &a = mesh.point(from), &b = mesh.point(to);
          const double length = (b - a).norm();
          if (!(length > 2.0 * tolerance) || !(length < INFINITY)) continue;
          if (std::binary_search(with_partner.begin(), with_partner.end(), h.idx())) {
            continue;  // most seams' edges
          }
          found.clear();
          points_near_segment(tree, a, b, tolerance, found);
          std::sort(found.begin(), found.end());  // a point near both halves is listed twice
          found.erase(std::unique(found.begin(), found.end()), found.end());
          const std::size_t first = junctions.size();
          for (const std::size_t index : found) {
            const VertexHandle v = points.vertices[index];
            const Point& p = mesh.point(v);
            if (v == from || v == to || (p - a).norm() <= tolerance ||
                (p - b).norm() <= tolerance) {
              continue;
            }
            const Projection onto = project(p, a, b);
            if (onto.distance > tolerance || !(onto.along > 0.0 && onto.along < 1.0)) continue;
            if (runs_back_along(mesh, v, onto.along, a, b, tolerance)) {
              junctions.push_back({h, v, onto.along});
            }
          }
          std::sort(junctions.begin() + static_cast<std::ptrdiff_t>(first), junctions.end(),
                    [](const TJunction& x, const TJunction& y) {
                      return std::tie(x.along, x.vertex) < std::tie(y.along, y.vertex);
                    });
        }
      });
  std::vector<TJunction> junctions;
  for (const auto& block : block_junctions)
    junctions.insert(junctions.end(), block.begin(), block.end());
  return junctions;
}

std::vector<VertexHandle> split_at_t_junctions(Mesh& mesh,
                                               const std::vector<TJunction>& junctions) {
  const ObjHandles obj = obj_handles(mesh);
  std::vector<VertexHandle> added;
  for (std::size_t first = 0; first < junctions.size();) {
    std::size_t last = first;
    while (last < junctions.size() && junctions[last].edge == junctions[first].edge) ++last;
    const HalfedgeHandle edge = junctions[first].edge;
    const VertexHandle a = mesh.from_vertex_handle(edge), b = mesh.to_vertex_handle(edge);
    // The face beside the boundary edge, before it is split: its corners' OBJ values.
    std::vector<std::pair<VertexHandle, CornerValues>> old_corners;
    if (obj.valid()) {
      const FaceHandle face = mesh.face_handle(mesh.opposite_halfedge_handle(edge));
      for (const auto corner : mesh.fh_range(face)) {
        old_corners.push_back(
            {mesh.to_vertex_handle(corner),
             {mesh.property(obj.texcoord, corner), mesh.property(obj.normal, corner)}});
      }
    }
    std::vector<std::pair<VertexHandle, double>> fresh;
    VertexHandle start = a;  // the junctions come in order from a to b
    for (std::size_t j = first; j < last; ++j) {
      // A copy: add_vertex may move the points the reference would point into.
      const Point at = mesh.point(junctions[j].vertex);
      const VertexHandle vertex = mesh.add_vertex(at);
      mesh.split_copy(mesh.edge_handle(mesh.find_halfedge(start, b)), vertex);
      fresh.emplace_back(vertex, junctions[j].along);
      added.push_back(vertex);
      start = vertex;
    }
    if (obj.valid()) set_split_corners(mesh, obj, a, b, fresh, old_corners);
    first = last;
  }
  return added;
}

}  // namespace holefill::detail
