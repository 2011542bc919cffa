#include "loop_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <tuple>
#include <unordered_map>

#include "nearest_neighbours.h"
#include "point_cloud_tree.h"

namespace holefill::detail {
namespace {

// The loop's vertices as points, and for each point the loop and its place on that loop.
struct LoopPoints {
  std::vector<Point> points;
  std::vector<int> loop;
  std::vector<int> place;
  std::vector<VertexHandle> vertex;
};

LoopPoints loop_points(const Mesh& mesh, const std::vector<const Hole*>& loops) {
  LoopPoints all;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    for (std::size_t i = 0; i < loops[l]->vertices.size(); ++i) {
      all.points.push_back(mesh.point(loops[l]->vertices[i]));
      all.loop.push_back(static_cast<int>(l));
      all.place.push_back(static_cast<int>(i));
      all.vertex.push_back(loops[l]->vertices[i]);
    }
  }
  return all;
}

// A nanoflann result set: the nearest point outside one group, not joined to the query vertex by
// a mesh edge (lowest index on ties).
class NearestElsewhere {
 public:
  NearestElsewhere(const Mesh& mesh, const LoopPoints& all, const std::vector<int>& group_of_point,
                   int group, VertexHandle from)
      : mesh_(mesh), all_(all), group_of_point_(group_of_point), group_(group), from_(from) {}

  double worstDist() const { return best_; }
  bool full() const { return index_ != kNone; }
  bool addPoint(double distance, std::uint32_t index) {
    if (distance > best_ || (distance == best_ && index > index_)) return true;
    if (group_of_point_[index] == group_) return true;
    if (mesh_.find_halfedge(from_, all_.vertex[index]).is_valid()) return true;
    best_ = distance;
    index_ = index;
    return true;
  }
  std::uint32_t index() const { return index_; }

  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

 private:
  const Mesh& mesh_;
  const LoopPoints& all_;
  const std::vector<int>& group_of_point_;
  int group_;
  VertexHandle from_;
  double best_ = std::numeric_limits<double>::max();
  std::uint32_t index_ = kNone;
};

struct Groups {
  std::vector<int> parent;
  int find(int g) {
    while (parent[g] != g) g = parent[g] = parent[parent[g]];
    return g;
  }
};

// A tree edge: (squared length, point on one side, point on the other).
using Edge = std::tuple<double, std::uint32_t, std::uint32_t>;

// One round: the shortest edge out of every group but the largest.
std::vector<Edge> shortest_edges_out(const Mesh& mesh, const LoopPoints& all,
                                     const PointCloudTree& tree, Groups& groups) {
  std::vector<int> group_of_point(all.points.size());
  std::vector<std::size_t> size(groups.parent.size(), 0);
  for (std::size_t p = 0; p < all.points.size(); ++p) {
    group_of_point[p] = groups.find(all.loop[p]);
    ++size[static_cast<std::size_t>(group_of_point[p])];
  }
  const auto largest = std::max_element(size.begin(), size.end()) - size.begin();
  std::vector<Edge> best(groups.parent.size(), Edge{INFINITY, 0, 0});
  for (std::size_t p = 0; p < all.points.size(); ++p) {
    const int g = group_of_point[p];
    if (g == largest) continue;
    NearestElsewhere nearest(mesh, all, group_of_point, g, all.vertex[p]);
    tree.findNeighbors(nearest, all.points[p].data(), nanoflann::SearchParams(32, 0.0f, false));
    if (nearest.index() == NearestElsewhere::kNone) continue;
    const Edge edge{(all.points[p] - all.points[nearest.index()]).sqrnorm(),
                    static_cast<std::uint32_t>(p), nearest.index()};
    if (edge < best[static_cast<std::size_t>(g)]) best[static_cast<std::size_t>(g)] = edge;
  }
  std::vector<Edge> found;
  for (const Edge& edge : best) {
    if (std::get<0>(edge) < INFINITY) found.push_back(edge);
  }
  return found;
}

// The tree's edges: Boruvka's rounds over the nearest-point searches; groups that find no edge
// (no other group's point at a finite distance, or only across mesh edges) hang from loops[0]'s
// first vertex.
std::vector<Edge> spanning_tree(const Mesh& mesh, const LoopPoints& all, std::size_t loops) {
  const PointCloud cloud{all.points};
  PointCloudTree tree(3, cloud);
  tree.buildIndex();
  Groups groups{std::vector<int>(loops)};
  std::iota(groups.parent.begin(), groups.parent.end(), 0);
  std::vector<Edge> chosen;
  for (std::size_t left = loops; left > 1;) {
    std::vector<Edge> found = shortest_edges_out(mesh, all, tree, groups);
    std::sort(found.begin(), found.end());
    const std::size_t before = left;
    for (const Edge& edge : found) {
      const int a = groups.find(all.loop[std::get<1>(edge)]);
      const int b = groups.find(all.loop[std::get<2>(edge)]);
      if (a == b) continue;
      groups.parent[static_cast<std::size_t>(a)] = b;
      chosen.push_back(edge);
      --left;
    }
    if (left < before) continue;
    for (std::uint32_t p = 0; p < all.points.size(); ++p) {
      const int g = groups.find(all.loop[p]);
      if (g == groups.find(0)) continue;
      groups.parent[static_cast<std::size_t>(g)] = groups.find(0);
      chosen.push_back(Edge{INFINITY, 0, p});
      --left;
    }
  }
  return chosen;
}

}  // namespace

LoopTree join_along_tree(const Mesh& mesh, const std::vector<const Hole*>& loops) {
  const LoopPoints all = loop_points(mesh, loops);
  const std::vector<Edge> edges = spanning_tree(mesh, all, loops.size());

  // Orient the tree from loops[0].
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> neighbours(loops.size());
  for (const auto& [length, p, q] : edges) {
    neighbours[static_cast<std::size_t>(all.loop[p])].emplace_back(p, q);
    neighbours[static_cast<std::size_t>(all.loop[q])].emplace_back(q, p);
  }
  // The loops hanging from each place of each loop, with the place on the child where its bridge
  // ends: children[loop][place] = {(child, place), ...}.
  std::vector<std::vector<std::vector<std::pair<int, int>>>> children(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) children[l].resize(loops[l]->vertices.size());
  std::vector<char> reached(loops.size(), 0);
  std::vector<int> queue{0};
  reached[0] = 1;
  LoopTree result;
  for (std::size_t next = 0; next < queue.size(); ++next) {
    for (const auto& [own, other] : neighbours[static_cast<std::size_t>(queue[next])]) {
      const auto child = static_cast<std::size_t>(all.loop[other]);
      if (reached[child]) continue;
      reached[child] = 1;
      queue.push_back(static_cast<int>(child));
      children[static_cast<std::size_t>(queue[next])][static_cast<std::size_t>(all.place[own])]
          .emplace_back(static_cast<int>(child), all.place[other]);
      result.bridges.emplace_back(all.vertex[own], all.vertex[other]);
    }
  }

  // Walk around the tree: each loop from the place its bridge arrives at, and at each place first
  // over the bridges to the loops hanging there and back (bridge.h's splice_loop, for all at once).
  Hole& polygon = result.polygon;
  polygon.id = loops[0]->id;
  double vertices = 0.0;
  for (const Hole* loop : loops) {
    const auto n = static_cast<double>(loop->size());
    polygon.perimeter += loop->perimeter;
    polygon.centroid += loop->centroid * n;
    polygon.mean_surrounding_edge_length += loop->mean_surrounding_edge_length * n;
    vertices += n;
  }
  polygon.centroid /= vertices;
  polygon.mean_surrounding_edge_length /= vertices;
  struct Visit {
    int loop, start;
    std::size_t step;
  };
  // The walk starts on loops[0] where no bridge leaves, so that the polygon's first vertex (an end
  // of the dynamic program's root chord) occurs once.
  const auto& at_root = children[0];
  const auto free_place = std::find_if(at_root.begin(), at_root.end(),
                                       [](const auto& hanging) { return hanging.empty(); });
  const int root_start =
      free_place == at_root.end() ? 0 : static_cast<int>(free_place - at_root.begin());
  std::vector<Visit> stack{{0, root_start, 0}};
  std::vector<std::size_t> next_child(all.points.size(), 0);
  std::vector<std::size_t> first_point(loops.size() + 1, 0);
  for (std::size_t l = 0; l < loops.size(); ++l)
    first_point[l + 1] = first_point[l] + loops[l]->size();
  while (!stack.empty()) {
    Visit& visit = stack.back();
    const Hole& loop = *loops[static_cast<std::size_t>(visit.loop)];
    if (visit.step == loop.size()) {
      if (visit.loop != 0) {
        polygon.vertices.push_back(loop.vertices[static_cast<std::size_t>(visit.start)]);
        polygon.halfedges.emplace_back();
      }
      stack.pop_back();
      continue;
    }
    const std::size_t place = (static_cast<std::size_t>(visit.start) + visit.step) % loop.size();
    const auto& hanging = children[static_cast<std::size_t>(visit.loop)][place];
    std::size_t& taken = next_child[first_point[static_cast<std::size_t>(visit.loop)] + place];
    if (taken < hanging.size()) {
      const auto [child, start] = hanging[taken++];
      polygon.vertices.push_back(loop.vertices[place]);
      polygon.halfedges.emplace_back();
      stack.push_back({child, start, 0});
      continue;
    }
    polygon.vertices.push_back(loop.vertices[place]);
    polygon.halfedges.push_back(loop.halfedges[place]);
    ++visit.step;
  }
  return result;
}

std::vector<std::pair<int, int>> chords_outside_corners(const Hole& joined,
                                                        const std::vector<Point>& points,
                                                        int nearest, int along) {
  const int n = static_cast<int>(points.size());
  std::unordered_map<int, int> occurrences;
  for (const auto v : joined.vertices) ++occurrences[v.idx()];
  // The plane: Newell's normal, and two axes in it.
  Point normal(0.0, 0.0, 0.0);
  for (int i = 0; i < n; ++i) normal += OpenMesh::cross(points[i], points[(i + 1) % n]);
  if (normal.sqrnorm() == 0.0) return {};
  normal.normalize();
  const Point helper = std::abs(normal[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
  const Point x_axis = OpenMesh::cross(helper, normal).normalized();
  const Point y_axis = OpenMesh::cross(normal, x_axis);
  // The angle of the direction from point i to point k, counter-clockwise about the normal.
  auto angle = [&](int i, int k) {
    const Point d = points[k] - points[i];
    return std::atan2(OpenMesh::dot(d, y_axis), OpenMesh::dot(d, x_axis));
  };
  const auto near = nearest_neighbours(points, nearest);
  std::vector<std::pair<int, int>> outside;
  for (int i = 0; i < n; ++i) {
    if (occurrences[joined.vertices[i].idx()] < 2) continue;
    // The wedge runs counter-clockwise from the edge out of i to the edge into it.
    const double out = angle(i, (i + 1) % n);
    const double wedge = std::remainder(angle(i, (i + n - 1) % n) - out, 2.0 * std::numbers::pi);
    const double width = wedge <= 0.0 ? wedge + 2.0 * std::numbers::pi : wedge;
    auto look_at = [&](int k) {
      const int low = std::min(i, k), high = std::max(i, k);
      if (high - low < 2 || high - low == n - 1) return;
      double turn = std::remainder(angle(i, k) - out, 2.0 * std::numbers::pi);
      if (turn < 0.0) turn += 2.0 * std::numbers::pi;
      if (!(turn > 0.0 && turn < width)) outside.emplace_back(low, high);
    };
    for (const int k : near[static_cast<std::size_t>(i)]) look_at(k);
    for (int step = 2; step <= along; ++step) {
      look_at(((i + step) % n + n) % n);
      look_at(((i - step) % n + n) % n);
    }
  }
  std::sort(outside.begin(), outside.end());
  outside.erase(std::unique(outside.begin(), outside.end()), outside.end());
  return outside;
}

}  // namespace holefill::detail
