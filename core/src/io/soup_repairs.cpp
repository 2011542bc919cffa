#include "soup_repairs.h"

#include <algorithm>
#include <bit>
#include <unordered_map>

#include "huge_pages.h"
#include "repair_checks.h"
#include "soup.h"

namespace holefill::io {
namespace {

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
                                EdgeUses& uses, unsigned threads) {
  // Where no two triangles run along an edge the same way, none is flipped: the neighbours, the
  // marks and the walk over every piece (a tenth of assembling a clean 1M-face mesh) are spared.
  if (!any_edge_run_the_same_way(uses, threads)) return 0;
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
std::vector<char> detach_non_manifold(const EdgeUses& uses, std::size_t triangles,
                                      unsigned threads) {
  std::vector<char> detached = huge_page_vector(triangles, char{0});
  if (!any_non_manifold_edge(uses, threads)) return detached;
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
                              std::vector<int>& origin, unsigned threads) {
  // Where no triangle is kept apart, whether any vertex has two fans is decided first on `threads`
  // threads (a clean mesh has none, and is spared the serial walks below).
  if (std::find(detached.begin(), detached.end(), 1) == detached.end() &&
      !any_vertex_with_several_fans(triangles, uses, threads)) {
    return 0;
  }
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

}  // namespace

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

std::size_t count_duplicate_positions(const std::vector<Point>& positions) {
  const std::vector<char> duplicate = repeats(
      positions.size(), [&positions](std::size_t i) { return PositionKey(positions[i]); },
      PositionHash{});
  return static_cast<std::size_t>(std::count(duplicate.begin(), duplicate.end(), 1));
}

std::vector<char> make_consistent(std::vector<Triangle>& triangles, std::vector<Triangle>& corners,
                                  std::vector<Point>& positions, std::vector<int>& origin,
                                  LoadReport& report, EdgeUses& uses, bool manifold_edges,
                                  unsigned threads) {
  report.faces_flipped =
      manifold_edges ? 0 : orient_consistently(triangles, corners, uses, threads);
  std::vector<char> detached = manifold_edges
                                   ? huge_page_vector(triangles.size(), char{0})
                                   : detach_non_manifold(uses, triangles.size(), threads);
  report.vertices_split = split_closed_fans(triangles, uses, detached, positions, origin, threads);
  if (report.vertices_split) uses = EdgeUses();
  return detached;
}

}  // namespace holefill::io
