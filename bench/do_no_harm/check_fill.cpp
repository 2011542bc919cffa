// holefill-check-fill INPUT.obj OUTPUT.obj: what a fill did to a mesh, checked independently
// of the library. Both files are read as plain OBJ (v and f lines; the first index of each
// corner), with no repairs. Vertices are matched by exact position, so that the loader's
// stitching and re-indexing do not count as changes.
//   - faces_changed: faces of the input (as position triples, in their orientation) that the
//     output lacks; vertices_moved: input positions that the output lacks. Both 0 when the
//     original vertices and faces survive bit for bit.
//   - added_faces: output faces that are not input faces (the patches); repaired_faces: output
//     faces that are not input faces either but lie on one the output lacks (within 1e-6 of the
//     bounding box's diagonal, holefill's stitching tolerance: a face split at a T-junction when
//     a seam was stitched), not counted as patches.
//   - patch_mesh_pairs / patch_patch_pairs: pairs (added face, other output face) whose
//     interiors meet, by the tests' exact GMP test (tests/support/exact_intersections.h, a
//     different method from the library's checks); touching at sides or corners does not count.
//   - nonmanifold_edges (an edge of more than two faces, or two faces the same way round) and
//     nonmanifold_vertices (a vertex whose faces form more than one fan), by the output's indices.
//   - boundary_edges / boundary_loops of the output, by position (a seam kept apart is closed).
// Prints one line of name=value pairs; exit 0 when nothing was harmed, 1 when something was,
// 2 on a usage or file error.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "exact_intersections.h"

namespace {

using holefill::Point;
using Face = std::array<int, 3>;

struct ObjFile {
  std::vector<Point> points;
  std::vector<Face> faces;
};

ObjFile read_obj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  ObjFile obj;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v") {
      Point p;
      words >> p[0] >> p[1] >> p[2];
      obj.points.push_back(p);
    } else if (kind == "f") {
      std::vector<int> corners;
      std::string corner;
      while (words >> corner) {
        const int index = std::stoi(corner.substr(0, corner.find('/')));
        corners.push_back(index < 0 ? static_cast<int>(obj.points.size()) + index : index - 1);
      }
      for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        obj.faces.push_back({corners[0], corners[i], corners[i + 1]});
      }
    }
  }
  return obj;
}

// Ids shared by the two files: one per distinct position.
class PositionIds {
 public:
  int id(const Point& p) {
    const auto [it, added] = ids_.try_emplace({p[0], p[1], p[2]}, static_cast<int>(ids_.size()));
    return it->second;
  }

 private:
  std::map<std::array<double, 3>, int> ids_;
};

// A face by position ids, rotated to start at its smallest id (orientation kept).
Face face_key(const Face& f, const std::vector<int>& id_of) {
  Face k{id_of[f[0]], id_of[f[1]], id_of[f[2]]};
  std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
  return k;
}

std::vector<int> ids_of(const ObjFile& obj, PositionIds& ids) {
  std::vector<int> id_of(obj.points.size());
  for (std::size_t v = 0; v < obj.points.size(); ++v) id_of[v] = ids.id(obj.points[v]);
  return id_of;
}

struct Box {
  Point low, high;
};

Box box_of(const std::array<Point, 3>& t) {
  Box b{t[0], t[0]};
  for (const auto& p : t) {
    for (int a = 0; a < 3; ++a) {
      b.low[a] = std::min(b.low[a], p[a]);
      b.high[a] = std::max(b.high[a], p[a]);
    }
  }
  return b;
}

std::array<Point, 3> corners_of(const ObjFile& obj, const Face& f) {
  return {obj.points[f[0]], obj.points[f[1]], obj.points[f[2]]};
}

// Whether every corner of `t` lies within `tolerance` of triangle `on` (its plane, and its box
// grown by the tolerance).
bool lies_on(const std::array<Point, 3>& t, const std::array<Point, 3>& on, double tolerance) {
  const Point normal = (on[1] - on[0]) % (on[2] - on[0]);
  const double length = normal.norm();
  if (length == 0) return false;
  const Box box = box_of(on);
  for (const auto& p : t) {
    if (std::abs((p - on[0]) | normal) > tolerance * length) return false;
    for (int a = 0; a < 3; ++a) {
      if (p[a] < box.low[a] - tolerance || p[a] > box.high[a] + tolerance) return false;
    }
  }
  return true;
}

// Pairs (added face, other face) that exactly intersect, each pair once: a sweep along x
// over the faces' boxes.
std::array<std::size_t, 2> count_intersections(const ObjFile& out, const std::vector<bool>& added) {
  const std::size_t n = out.faces.size();
  std::vector<std::array<Point, 3>> corners(n);
  std::vector<Box> boxes(n);
  for (std::size_t f = 0; f < n; ++f) {
    for (int c = 0; c < 3; ++c) corners[f][c] = out.points[out.faces[f][c]];
    boxes[f] = box_of(corners[f]);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].low[0] < boxes[b].low[0]; });
  std::array<std::size_t, 2> pairs{0, 0};  // with the mesh, between patch faces
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = order[i];
    for (std::size_t j = i + 1; j < n && boxes[order[j]].low[0] <= boxes[a].high[0]; ++j) {
      const std::size_t b = order[j];
      if (!added[a] && !added[b]) continue;
      bool apart = false;
      for (int axis = 1; axis < 3; ++axis) {
        apart = apart || boxes[a].high[axis] < boxes[b].low[axis] ||
                boxes[b].high[axis] < boxes[a].low[axis];
      }
      if (apart || !holefill::testing::exactly_intersect(corners[a], corners[b])) continue;
      ++pairs[added[a] && added[b] ? 1 : 0];
    }
  }
  return pairs;
}

// Edges used by more than two faces or twice the same way round, and vertices whose faces do
// not form one fan (their link is not one path or cycle), by the file's indices.
std::array<std::size_t, 2> count_nonmanifold(const ObjFile& out) {
  std::map<std::pair<int, int>, int> directed, undirected;
  for (const auto& f : out.faces) {
    for (int c = 0; c < 3; ++c) {
      const int a = f[c], b = f[(c + 1) % 3];
      ++directed[{a, b}];
      ++undirected[{std::min(a, b), std::max(a, b)}];
    }
  }
  std::size_t edges = 0;
  for (const auto& [e, count] : undirected) {
    edges += count > 2 || directed[{e.first, e.second}] > 1 || directed[{e.second, e.first}] > 1;
  }
  // Each face adds an arc (next -> previous corner) to its corner's link; a fan is one chain.
  std::vector<std::vector<std::pair<int, int>>> link(out.points.size());
  for (const auto& f : out.faces) {
    for (int c = 0; c < 3; ++c) link[f[c]].push_back({f[(c + 1) % 3], f[(c + 2) % 3]});
  }
  std::size_t vertices = 0;
  for (const auto& arcs : link) {
    if (arcs.empty()) continue;
    std::map<int, int> next;
    for (const auto& [from, to] : arcs) next[from] = to;
    if (next.size() != arcs.size()) {  // two faces leave the vertex along one edge
      ++vertices;
      continue;
    }
    std::size_t starts = 0;  // chains: arcs whose start no arc ends at
    std::map<int, int> ends;
    for (const auto& [from, to] : arcs) ++ends[to];
    for (const auto& [from, to] : arcs) starts += ends.count(from) == 0;
    if (starts > 1) {
      ++vertices;
    } else if (starts == 0) {  // a cycle must use every arc
      std::size_t length = 1;
      for (int v = next.begin()->second; v != next.begin()->first && length <= arcs.size();
           v = next.count(v) ? next[v] : next.begin()->first) {
        ++length;
      }
      vertices += length != arcs.size();
    }
  }
  return {edges, vertices};
}

// Boundary edges by position: directed edges whose reverse no face has; and their loops.
std::array<std::size_t, 2> count_boundary(const ObjFile& out, const std::vector<int>& id_of) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : out.faces) {
    for (int c = 0; c < 3; ++c) ++directed[{id_of[f[c]], id_of[f[(c + 1) % 3]]}];
  }
  std::vector<std::pair<int, int>> open;
  for (const auto& [e, count] : directed) {
    if (directed.count({e.second, e.first}) == 0) open.push_back(e);
  }
  // Loops: components of the open edges joined at their ends.
  std::map<int, int> parent;
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& [a, b] : open) parent.try_emplace(a, a), parent.try_emplace(b, b);
  for (const auto& [a, b] : open) parent[find(a)] = find(b);
  std::size_t loops = 0;
  for (const auto& [v, p] : parent) loops += find(v) == v;
  return {open.size(), loops};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: holefill-check-fill INPUT.obj OUTPUT.obj\n";
    return 2;
  }
  try {
    const ObjFile in = read_obj(argv[1]), out = read_obj(argv[2]);
    PositionIds ids;
    const auto in_ids = ids_of(in, ids), out_ids = ids_of(out, ids);
    std::multiset<Face> remaining;
    for (const auto& f : in.faces) remaining.insert(face_key(f, in_ids));
    std::vector<bool> added(out.faces.size());
    for (std::size_t f = 0; f < out.faces.size(); ++f) {
      const auto it = remaining.find(face_key(out.faces[f], out_ids));
      added[f] = it == remaining.end();
      if (!added[f]) remaining.erase(it);
    }
    // Added faces that lie on an input face the output lacks: repairs, not patches.
    Box all = box_of(corners_of(in, in.faces.front()));
    for (const auto& p : in.points) all = box_of({all.low, all.high, p});
    const double tolerance = 1e-6 * (all.high - all.low).norm();
    std::vector<std::array<Point, 3>> lacking;
    for (const auto& f : in.faces) {
      if (remaining.count(face_key(f, in_ids))) lacking.push_back(corners_of(in, f));
    }
    std::size_t repaired = 0;
    for (std::size_t f = 0; f < out.faces.size(); ++f) {
      if (!added[f]) continue;
      const auto t = corners_of(out, out.faces[f]);
      if (std::any_of(lacking.begin(), lacking.end(),
                      [&](const auto& on) { return lies_on(t, on, tolerance); })) {
        added[f] = false;
        ++repaired;
      }
    }
    std::vector<bool> in_output(1 + std::max(0, *std::max_element(out_ids.begin(), out_ids.end())));
    for (const int id : out_ids) in_output[id] = true;
    std::size_t moved = 0;
    for (const int id : in_ids) moved += id >= static_cast<int>(in_output.size()) || !in_output[id];
    const auto pairs = count_intersections(out, added);
    const auto nonmanifold = count_nonmanifold(out);
    const auto boundary = count_boundary(out, out_ids);
    std::cout << "added_faces=" << std::count(added.begin(), added.end(), true)
              << " patch_mesh_pairs=" << pairs[0] << " patch_patch_pairs=" << pairs[1]
              << " repaired_faces=" << repaired << " faces_changed=" << remaining.size()
              << " vertices_moved=" << moved << " nonmanifold_edges=" << nonmanifold[0]
              << " nonmanifold_vertices=" << nonmanifold[1] << " boundary_edges=" << boundary[0]
              << " boundary_loops=" << boundary[1] << "\n";
    const bool harmed =
        pairs[0] + pairs[1] + remaining.size() + moved + nonmanifold[0] + nonmanifold[1] > 0;
    return harmed ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "holefill-check-fill: " << e.what() << "\n";
    return 2;
  }
}
