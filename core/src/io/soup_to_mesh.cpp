#include "soup_to_mesh.h"

#include <algorithm>
#include <bit>
#include <numeric>
#include <unordered_map>

#include "holefill/triangulate.h"
#include "huge_pages.h"
#include "mesh_from_triangles.h"
#include "soup_attributes.h"
#include "two_parts.h"
#include "two_threads.h"

namespace holefill::io {
namespace fs = std::filesystem;

namespace {

// Polygons up to this many corners are triangulated by the max-min angle dynamic program (which
// also keeps a non-convex polygon from folding over itself); larger ones as a fan.
constexpr std::size_t kMaxOptimalPolygon = 64;

// The triangles (by positions in ks) that cut the polygon of soup corners ks, more than three
// with no two consecutive ones at one vertex.
std::vector<Triangle> polygon_pieces(const Soup& soup, const std::vector<int>& ks) {
  auto vertex = [&soup](int k) { return soup.corners[k]; };
  const int n = static_cast<int>(ks.size());
  std::vector<Triangle> pieces;
  if (ks.size() <= kMaxOptimalPolygon) {
    HolePolygon polygon;
    for (const int k : ks) polygon.points.push_back(soup.positions[vertex(k)]);
    polygon.outside_normals.assign(ks.size(), Point(0.0, 0.0, 0.0));
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (vertex(ks[i]) == vertex(ks[j])) polygon.forbidden_chords.emplace_back(i, j);
      }
    }
    if (const auto optimal = triangulate_polygon(polygon, TriangulateOptions{})) {
      for (const auto& t : optimal->triangles) pieces.push_back({t[0], t[1], t[2]});
    }
  }
  if (pieces.empty()) {
    for (int c = 1; c + 1 < n; ++c) pieces.push_back({0, c, c + 1});
  }
  return pieces;
}

// Triangulates the soup's polygon f: each triangle's corners (soup positions) go to `triangles`
// and, with `corners`, the soup corners (indices into soup.corners) they came from to `corners`.
void triangulate_face(const Soup& soup, std::size_t f, std::vector<int>& ks,
                      std::vector<Triangle>& triangles, std::vector<Triangle>* corners,
                      LoadReport& report) {
  ks.clear();  // the polygon's soup corners (the caller's, to spare an allocation per face)
  for (std::size_t k = soup.face_begin(f); k < soup.face_end[f]; ++k) {
    ks.push_back(static_cast<int>(k));
  }
  auto vertex = [&soup](int k) { return soup.corners[k]; };
  // Repeated consecutive corners (the last one repeating the first included) add nothing.
  ks.erase(std::unique(ks.begin(), ks.end(), [&](int a, int b) { return vertex(a) == vertex(b); }),
           ks.end());
  while (ks.size() > 1 && vertex(ks.front()) == vertex(ks.back())) ks.pop_back();
  if (ks.size() < 3) {
    ++report.degenerate_faces_dropped;
    return;
  }
  if (ks.size() == 3) {  // most faces: nothing to cut
    triangles.push_back({vertex(ks[0]), vertex(ks[1]), vertex(ks[2])});
    if (corners) corners->push_back({ks[0], ks[1], ks[2]});
    return;
  }
  ++report.polygons_triangulated;
  const std::vector<Triangle> pieces = polygon_pieces(soup, ks);
  bool dropped = false;
  for (const auto& p : pieces) {
    const Triangle t{vertex(ks[p[0]]), vertex(ks[p[1]]), vertex(ks[p[2]])};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      dropped = true;
      continue;
    }
    triangles.push_back(t);
    if (corners) corners->push_back({ks[p[0]], ks[p[1]], ks[p[2]]});
  }
  if (dropped) ++report.degenerate_faces_dropped;
}

// Which of the items 0..count-1 have the key of an earlier one, in one pass over a flat
// open-addressing table (a node per item in a std::unordered_set, or a sort of all the keys, took
// most of the time of these checks on big meshes). The slot comes from the hash's high bits
// after a multiplication (positions' low bits are often all zero), and each entry keeps 32 bits
// of the hash, so that a full key is read only when those match.
template <class KeyOf, class Hash>
std::vector<char> repeats(std::size_t count, KeyOf key_of, Hash hash) {
  const int bits = std::bit_width(2 * count + 1);
  // hash bits, 1 + index (0: empty)
  std::vector<std::uint64_t> table = huge_page_vector(std::size_t{1} << bits, std::uint64_t{0});
  std::vector<char> repeat = huge_page_vector(count, char{0});
  for (std::size_t i = 0; i < count; ++i) {
    const auto key = key_of(i);
    const std::uint64_t mixed = static_cast<std::uint64_t>(hash(key)) * 0x9E3779B97F4A7C15ull;
    const std::uint64_t tag = mixed << 32;
    std::size_t slot = mixed >> (64 - bits);
    for (; table[slot] != 0; slot = (slot + 1) & (table.size() - 1)) {
      if ((table[slot] & ~0xFFFFFFFFull) == tag && key_of((table[slot] & 0xFFFFFFFFu) - 1) == key) {
        break;
      }
    }
    if (table[slot] != 0) {
      repeat[i] = 1;
    } else {
      table[slot] = tag | static_cast<std::uint32_t>(i + 1);
    }
  }
  return repeat;
}

// Removes triangles with the same corners in the same cyclic order as an earlier one, and their
// entries in `sources` (the face each triangle came from) and `corners` (each when not empty).
std::size_t drop_duplicate_triangles(std::vector<Triangle>& triangles, std::vector<int>& sources,
                                     std::vector<Triangle>& corners) {
  auto canonical = [&triangles](std::size_t i) {
    Triangle t = triangles[i];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  auto hash = [](const Triangle& t) {
    std::uint64_t h = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t[0])) << 32 |
                       static_cast<std::uint32_t>(t[1])) *
                      0x9E3779B97F4A7C15ull;
    h = (h ^ static_cast<std::uint32_t>(t[2])) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<std::size_t>(h ^ (h >> 31));
  };
  const std::vector<char> duplicate = repeats(triangles.size(), canonical, hash);
  const auto count = static_cast<std::size_t>(std::count(duplicate.begin(), duplicate.end(), 1));
  if (count == 0) return 0;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (duplicate[i]) continue;
    if (!sources.empty()) sources[kept] = sources[i];
    if (!corners.empty()) corners[kept] = corners[i];
    triangles[kept++] = triangles[i];
  }
  triangles.resize(kept);
  if (!sources.empty()) sources.resize(kept);
  if (!corners.empty()) corners.resize(kept);
  return count;
}

// A triangle's neighbours across its edges (up to three): how many, and for each whether it must
// take the opposite orientation, in one byte (the count in the low two bits).
class NeighbourFlips {
 public:
  int count() const { return bits_ & 3; }
  bool must_flip(int l) const { return (bits_ >> (2 + l) & 1) != 0; }
  void add(bool opposite) {
    bits_ = static_cast<std::uint8_t>((bits_ | (opposite ? 1 : 0) << (2 + count())) + 1);
  }

 private:
  std::uint8_t bits_ = 0;
};

// Flips triangles so that neighbours across every edge with exactly two triangles use it in
// opposite directions; per connected piece, the orientation most triangles have wins. Returns
// the number flipped, and turns `corners` (when not empty) and the triangles' `uses` (their
// EdgeUses) alike. Pieces that cannot be oriented (a Moebius strip) keep a conflict, which
// detach_non_manifold resolves.
std::size_t orient_consistently(std::vector<Triangle>& triangles, std::vector<Triangle>& corners,
                                EdgeUses& uses) {
  // Where no two triangles run along an edge the same way, none is flipped: the neighbours, the
  // marks and the walk over every piece (a tenth of assembling a clean 1M-face mesh) are spared.
  bool any_conflict = false;
  uses.for_each_edge([&](int, std::size_t i, std::size_t j) {
    any_conflict = any_conflict || (j - i == 2 && uses[i].triangle() != uses[i + 1].triangle() &&
                                    uses[i].forward() == uses[i + 1].forward());
  });
  if (!any_conflict) return 0;
  const int count = static_cast<int>(triangles.size());
  // Up to three neighbours per triangle, and whether each must take the opposite orientation.
  auto neighbour = huge_page_vector(triangles.size(), std::array<int, 3>{-1, -1, -1});
  auto links = huge_page_vector(triangles.size(), NeighbourFlips());
  uses.for_each_edge([&](int, std::size_t i, std::size_t j) {
    if (j - i != 2 || uses[i].triangle() == uses[i + 1].triangle()) return;
    const int a = uses[i].triangle(), b = uses[i + 1].triangle();
    const bool opposite = uses[i].forward() == uses[i + 1].forward();
    neighbour[a][links[a].count()] = b;
    links[a].add(opposite);
    neighbour[b][links[b].count()] = a;
    links[b].add(opposite);
  });
  // -1 not reached yet; 0 or 1 whether the triangle takes the other orientation than its piece's
  // first; kTurned once it is flipped (no array of its own at the peak of loading a big mesh).
  constexpr signed char kTurned = 2;
  std::vector<signed char> flip = huge_page_vector(triangles.size(), static_cast<signed char>(-1));
  std::vector<int> piece, queue;
  piece.reserve(triangles.size());  // a connected mesh is one piece: it grew to all by doubling
  std::size_t flipped = 0;
  for (int seed = 0; seed < count; ++seed) {
    if (flip[seed] >= 0) continue;
    piece.clear();
    queue.assign(1, seed);
    flip[seed] = 0;
    while (!queue.empty()) {
      const int t = queue.back();
      queue.pop_back();
      piece.push_back(t);
      for (int l = 0; l < links[t].count(); ++l) {
        const int other = neighbour[t][l];
        if (flip[other] >= 0) continue;
        flip[other] = static_cast<signed char>(flip[t] ^ (links[t].must_flip(l) ? 1 : 0));
        queue.push_back(other);
      }
    }
    const auto marked = static_cast<std::size_t>(
        std::count_if(piece.begin(), piece.end(), [&](int t) { return flip[t] == 1; }));
    const signed char turn = 2 * marked > piece.size() ? 0 : 1;
    for (const int t : piece) {
      if (flip[t] != turn) continue;
      std::swap(triangles[t][1], triangles[t][2]);
      if (!corners.empty()) std::swap(corners[t][1], corners[t][2]);
      flip[t] = kTurned;
      ++flipped;
    }
  }
  // A flipped triangle runs along each of its edges the other way (the edges stay).
  if (flipped == 0) return 0;
  for (std::size_t k = 0; k < uses.size(); ++k) {
    if (flip[uses[k].triangle()] == kTurned) uses[k].reverse();
  }
  return flipped;
}

// Marks the triangles that must be kept apart so that every edge is used at most twice, in
// opposite directions: on each edge the first triangle and the first one after it running the
// other way stay; later ones (a third sheet on the edge, a fin) are detached.
std::vector<char> detach_non_manifold(const EdgeUses& uses, std::size_t triangles) {
  std::vector<char> detached = huge_page_vector(triangles, char{0});
  uses.for_each_edge([&](int, std::size_t i, std::size_t j) {
    int kept = 0;
    bool first_forward = false;
    for (std::size_t k = i; k < j; ++k) {
      if (detached[uses[k].triangle()]) continue;
      if (kept == 0) {
        first_forward = uses[k].forward();
        kept = 1;
      } else if (kept == 1 && uses[k].forward() != first_forward) {
        kept = 2;
      } else {
        detached[uses[k].triangle()] = 1;
      }
    }
  });
  return detached;
}

// The fans of triangles around each vertex: wedges, (triangle, corner) pairs, joined across the
// edges two live triangles share, and which wedges lie on a boundary edge.
class WedgeFans {
 public:
  WedgeFans(const std::vector<Triangle>& triangles, const EdgeUses& uses,
            const std::vector<char>& detached)
      : parent_(huge_page_vector(3 * triangles.size(), 0)),
        open_(huge_page_vector(3 * triangles.size(), char{0})) {
    for (std::size_t w = 0; w < parent_.size(); ++w) parent_[w] = static_cast<int>(w);
    auto wedge = [&triangles](int t, int vertex) {
      const auto& c = triangles[t];
      return 3 * t + (c[0] == vertex ? 0 : c[1] == vertex ? 1 : 2);
    };
    uses.for_each_edge([&](int smaller, std::size_t i, std::size_t j) {
      int live[2], count = 0;
      for (std::size_t k = i; k < j; ++k) {
        if (!detached[uses[k].triangle()] && count < 2) live[count++] = uses[k].triangle();
      }
      const int a = smaller, b = uses[i].larger();
      if (count == 1) {
        open_[wedge(live[0], a)] = open_[wedge(live[0], b)] = 1;
      } else if (count == 2) {
        for (const int v : {a, b}) parent_[fan(wedge(live[0], v))] = fan(wedge(live[1], v));
      }
    });
  }

  // The fan of wedge w, named by one of its wedges.
  int fan(int w) {
    while (parent_[w] != w) w = parent_[w] = parent_[parent_[w]];
    return w;
  }
  bool open(int w) const { return open_[w] != 0; }

 private:
  std::vector<int> parent_;
  std::vector<char> open_;
};

// The (vertex, fan) pairs of the vertices with more than one fan, sorted, each once.
std::vector<std::pair<int, int>> fans_of_shared_vertices(const std::vector<Triangle>& triangles,
                                                         const std::vector<char>& detached,
                                                         std::size_t vertices, WedgeFans& wedges) {
  std::vector<int> first_fan = huge_page_vector(vertices, -1);
  std::vector<char> several = huge_page_vector(vertices, char{0});
  const int count = static_cast<int>(triangles.size());
  for (int t = 0; t < count; ++t) {
    if (detached[t]) continue;
    for (int c = 0; c < 3; ++c) {
      const int v = triangles[t][c], fan = wedges.fan(3 * t + c);
      if (first_fan[v] < 0) first_fan[v] = fan;
      if (first_fan[v] != fan) several[v] = 1;
    }
  }
  std::vector<std::pair<int, int>> fans;
  for (int t = 0; t < count; ++t) {
    if (detached[t]) continue;
    for (int c = 0; c < 3; ++c) {
      if (several[triangles[t][c]]) fans.emplace_back(triangles[t][c], wedges.fan(3 * t + c));
    }
  }
  std::sort(fans.begin(), fans.end());
  fans.erase(std::unique(fans.begin(), fans.end()), fans.end());
  return fans;
}

// OpenMesh cannot store a vertex whose closed fan of triangles is not all it has (two cones
// touching at their tips). Each such closed fan gets its own copy of the vertex, at the same
// position (appended to `positions`), so both surfaces stay closed. Fans with a boundary may
// share a vertex: that is a pinched boundary, which OpenMesh stores. Returns the copies made;
// `origin` (when not empty) gets the vertex each copy was made from. `uses` are the triangles'
// EdgeUses.
std::size_t split_closed_fans(std::vector<Triangle>& triangles, const EdgeUses& uses,
                              const std::vector<char>& detached, std::vector<Point>& positions,
                              std::vector<int>& origin) {
  WedgeFans wedges(triangles, uses, detached);
  const auto fans = fans_of_shared_vertices(triangles, detached, positions.size(), wedges);
  if (fans.empty()) return 0;
  std::vector<char> open_fan = huge_page_vector(3 * triangles.size(), char{0});
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    for (int c = 0; c < 3; ++c) {
      if (!detached[t] && wedges.open(3 * t + c)) open_fan[wedges.fan(3 * t + c)] = 1;
    }
  }
  std::unordered_map<int, int> copy_of_fan;  // fan -> its own vertex
  for (std::size_t i = 0; i < fans.size();) {
    std::size_t j = i;
    while (j < fans.size() && fans[j].first == fans[i].first) ++j;
    bool original_taken = std::any_of(fans.begin() + static_cast<std::ptrdiff_t>(i),
                                      fans.begin() + static_cast<std::ptrdiff_t>(j),
                                      [&](const auto& fan) { return open_fan[fan.second] != 0; });
    for (std::size_t k = i; k < j; ++k) {
      if (open_fan[fans[k].second]) continue;
      if (!original_taken) {
        original_taken = true;
        continue;
      }
      copy_of_fan[fans[k].second] = static_cast<int>(positions.size());
      positions.push_back(positions[fans[k].first]);
      if (!origin.empty()) origin.push_back(fans[k].first);
    }
    i = j;
  }
  if (copy_of_fan.empty()) return 0;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    if (detached[t]) continue;
    for (int c = 0; c < 3; ++c) {
      const auto found = copy_of_fan.find(wedges.fan(3 * t + c));
      if (found != copy_of_fan.end()) triangles[t][c] = found->second;
    }
  }
  return copy_of_fan.size();
}

std::size_t count_duplicate_positions(const std::vector<Point>& positions) {
  const std::vector<char> duplicate = repeats(
      positions.size(), [&positions](std::size_t i) { return PositionKey(positions[i]); },
      PositionHash{});
  return static_cast<std::size_t>(std::count(duplicate.begin(), duplicate.end(), 1));
}

// Orients the triangles, marks those to keep apart and splits the vertices where closed fans
// touch (counted in `report`); returns the marks. One EdgeUses serves all three (flips keep the
// edges); it is handed on in `uses` when it still describes the triangles (no vertex split),
// else freed before the mesh is assembled.
std::vector<char> make_consistent(std::vector<Triangle>& triangles, std::vector<Triangle>& corners,
                                  std::vector<Point>& positions, std::vector<int>& origin,
                                  LoadReport& report, EdgeUses& uses) {
  uses = EdgeUses(triangles);
  report.faces_flipped = orient_consistently(triangles, corners, uses);
  std::vector<char> detached = detach_non_manifold(uses, triangles.size());
  report.vertices_split = split_closed_fans(triangles, uses, detached, positions, origin);
  if (report.vertices_split) uses = EdgeUses();
  return detached;
}

// The soup's polygons as triangles (by soup position), with, when tracked, the soup corners each
// was made of and the polygon each came from.
struct Triangulation {
  std::vector<Triangle> triangles;
  std::vector<Triangle> corners;  // when tracked
  std::vector<int> face;          // when tracked
};

// Triangulates the soup's faces [begin, end) onto the end of `into`, counting in `report`.
void triangulate_faces(const Soup& soup, std::size_t begin, std::size_t end, bool track_origins,
                       bool track_corners, Triangulation& into, LoadReport& report) {
  std::vector<int> polygon;  // the polygon's soup corners, one allocation for all faces
  for (std::size_t f = begin; f < end; ++f) {
    triangulate_face(soup, f, polygon, into.triangles, track_corners ? &into.corners : nullptr,
                     report);
    if (track_origins) into.face.resize(into.triangles.size(), static_cast<int>(f));
  }
}

// Gives `into` room for the triangles of the soup's faces [begin, end): a polygon of k corners
// makes k - 2 triangles at most, so a mesh of triangles fills the first `likely` (the room allows
// for any polygons).
void reserve_triangles(const Soup& soup, std::size_t begin, std::size_t end, bool track_origins,
                       bool track_corners, Triangulation& into) {
  const std::size_t faces = end - begin;
  const std::size_t corners = begin == end ? 0 : soup.face_end[end - 1] - soup.face_begin(begin);
  const std::size_t room = corners / 3 + faces;
  const std::size_t likely = corners - std::min(corners, 2 * faces);
  reserve_on_huge_pages(into.triangles, room, likely);
  if (track_origins) reserve_on_huge_pages(into.face, room, likely);
  if (track_corners) reserve_on_huge_pages(into.corners, room, likely);
}

// The soup's polygons as triangles, in the order of the faces; on two threads (`two`), each
// triangulates half of the faces, and the second half's triangles follow the first's.
Triangulation triangulate_soup(const Soup& soup, bool track_origins, bool track_corners, bool two,
                               LoadReport& report) {
  Triangulation first, second;
  const std::size_t faces = soup.face_count(), middle = two ? faces / 2 : faces;
  reserve_triangles(soup, 0, faces, track_origins, track_corners, first);
  LoadReport second_report;
  run_both(
      two, [&] { triangulate_faces(soup, 0, middle, track_origins, track_corners, first, report); },
      [&] {
        if (middle == faces) return;
        reserve_triangles(soup, middle, faces, track_origins, track_corners, second);
        triangulate_faces(soup, middle, faces, track_origins, track_corners, second, second_report);
      });
  report.polygons_triangulated += second_report.polygons_triangulated;
  report.degenerate_faces_dropped += second_report.degenerate_faces_dropped;
  append_and_free(first.triangles, second.triangles);
  append_and_free(first.corners, second.corners);
  append_and_free(first.face, second.face);
  return first;
}

// Where the mesh's elements came from in the soup (soup_attributes.h), from where they came from
// in the triangles (`sources`), each triangle's polygon and corners, and each vertex's soup
// position (`origin`): those arrays themselves (taken) when the mesh's elements are the triangles'
// and positions' (no face detached: copies of them were 18 MB of a 1M-face textured OBJ's load),
// else composed with the sources, each half of the vertices and faces on its own thread when
// `two`.
SoupOrigins origins_of(const MeshSources& sources, Triangulation& triangulation,
                       std::vector<int>& origin, bool track_corners, bool two) {
  SoupOrigins origins;
  if (sources.identity()) {
    origins.vertex = std::move(origin);
    origins.face = std::move(triangulation.face);
    if (track_corners) origins.face_corners = std::move(triangulation.corners);
    return origins;
  }
  // On huge pages, as the mesh's arrays they are read into.
  origins.vertex = huge_page_vector(sources.vertex.size(), 0);
  origins.face = huge_page_vector(sources.face.size(), 0);
  if (track_corners) origins.face_corners = huge_page_vector(sources.face.size(), Triangle{});
  run_in_halves(two, sources.vertex.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) origins.vertex[v] = origin[sources.vertex[v]];
  });
  run_in_halves(two, sources.face.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const int t = sources.face[f];
      origins.face[f] = triangulation.face[t];
      if (track_corners) origins.face_corners[f] = triangulation.corners[t];
    }
  });
  return origins;
}

}  // namespace

// Where each triangle and vertex came from is followed only when the soup carries attributes to
// copy: on a big mesh with none, those arrays were a tenth of the peak.
Mesh build_mesh(Soup soup, LoadReport& report, std::size_t two_threads_from) {
  const bool track_origins = has_attributes(soup);
  const bool track_corners = has_corner_values(soup);
  const bool two = use_two_threads(soup.face_count(), two_threads_from);
  Triangulation triangulation = triangulate_soup(soup, track_origins, track_corners, two, report);
  // The polygons are triangles now.
  std::vector<int>().swap(soup.corners);
  std::vector<std::size_t>().swap(soup.face_end);
  soup.face_line = FaceLines();
  // Duplicate faces and duplicate positions, one beside the other.
  const bool count_positions = report.format != "stl";
  std::size_t duplicate_positions = 0;
  run_both(
      two,
      [&] {
        report.duplicate_faces_dropped = drop_duplicate_triangles(
            triangulation.triangles, triangulation.face, triangulation.corners);
      },
      [&] {
        if (count_positions) duplicate_positions = count_duplicate_positions(soup.positions);
      });
  report.duplicate_positions = duplicate_positions;
  std::vector<Point> positions = std::move(soup.positions);
  const std::size_t original_vertices = positions.size();
  std::vector<int> origin;  // the soup position of each vertex, when tracked
  if (track_origins) {
    reserve_on_huge_pages(origin, positions.size());
    origin.resize(positions.size());
    std::iota(origin.begin(), origin.end(), 0);
  }
  EdgeUses uses;
  std::vector<char> detached = make_consistent(triangulation.triangles, triangulation.corners,
                                               positions, origin, report, uses);
  MeshSources sources;
  Mesh mesh =
      assemble(std::move(positions), std::move(triangulation.triangles), std::move(detached),
               original_vertices, report, track_origins ? &sources : nullptr, std::move(uses),
               two_threads_from, [&soup](Mesh& empty) { add_soup_properties(soup, empty); });
  keep_file_format(soup, mesh);
  if (!track_origins) return mesh;
  const SoupOrigins origins = origins_of(sources, triangulation, origin, track_corners, two);
  copy_soup_attributes(soup, origins, mesh, two);
  return mesh;
}

void add_warnings(LoadReport& report) {
  auto warn = [&report](std::size_t count, const std::string& text) {
    if (count) report.warnings.push_back(std::to_string(count) + " " + text);
  };
  warn(report.polygons_triangulated, "polygons with more than 3 corners were triangulated");
  warn(report.degenerate_faces_dropped,
       "degenerate faces (a vertex used twice, or fewer than 3 corners) were dropped");
  warn(report.duplicate_faces_dropped,
       "duplicate faces (the same corners as an earlier face) were dropped");
  warn(report.faces_flipped,
       "faces were flipped to agree with the orientation of their neighbours");
  warn(report.faces_detached, "non-manifold faces were kept on their own copies of their vertices");
  warn(report.vertices_split,
       "vertices where closed surfaces touch were split, one copy per surface");
  warn(report.duplicate_positions,
       "vertices have exactly the position of another vertex (kept apart: the surface may be "
       "cut open there)");
  warn(report.isolated_vertices, "vertices are used by no face (kept)");
  warn(report.elements_ignored, "line, point or curve elements were ignored (not surfaces)");
}

}  // namespace holefill::io
