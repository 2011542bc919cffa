// Triangles by vertex index, their edges, and the Mesh they make once the repairs (soup_to_mesh)
// have made them consistent.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "holefill/io.h"

namespace holefill::io {

using Triangle = std::array<int, 3>;

// One triangle's use of an undirected edge, in 12 bytes (three per triangle: the largest array
// while the repairs run, 16 bytes a use before).
class EdgeUse {
 public:
  EdgeUse() = default;
  // `edge`: the smaller vertex index in the high half, the larger in the low; `forward`: the
  // triangle runs from the smaller to the larger (triangle indices are below 2^31).
  EdgeUse(std::uint64_t edge, int triangle, bool forward)
      : smaller_(static_cast<std::uint32_t>(edge >> 32)),
        larger_(static_cast<std::uint32_t>(edge)),
        triangle_(static_cast<std::uint32_t>(triangle) | (forward ? kForward : 0)) {}

  std::uint64_t edge() const { return std::uint64_t{smaller_} << 32 | larger_; }
  int smaller() const { return static_cast<int>(smaller_); }
  int larger() const { return static_cast<int>(larger_); }
  int triangle() const { return static_cast<int>(triangle_ & ~kForward); }
  bool forward() const { return (triangle_ & kForward) != 0; }
  // The triangle was flipped: it runs along the edge the other way.
  void reverse() { triangle_ ^= kForward; }
  bool operator<(const EdgeUse& other) const {
    return edge() != other.edge() ? edge() < other.edge() : triangle() < other.triangle();
  }

 private:
  static constexpr std::uint32_t kForward = 0x80000000u;
  std::uint32_t smaller_ = 0, larger_ = 0;
  std::uint32_t triangle_ = 0;  // the triangle's index, kForward when it runs forward
};
static_assert(sizeof(EdgeUse) == 12);

// Every use of an edge by a triangle, sorted by edge (then triangle).
std::vector<EdgeUse> edge_uses(const std::vector<Triangle>& triangles);

// Calls visit(first, last) for each run of uses of one edge.
template <class Visit>
void for_each_edge(const std::vector<EdgeUse>& uses, Visit&& visit) {
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].edge() == uses[i].edge()) ++j;
    visit(i, j);
    i = j;
  }
}

// Where each element of an assembled mesh came from: the index of its input position (vertex)
// or input triangle (face).
struct MeshSources {
  std::vector<int> vertex, face;
};

// The mesh of `triangles` over `positions`. Triangles marked in `detached` are kept on their own
// copies of their corners (appended after the positions); the others must be consistent: every
// edge used at most twice, in opposite directions, and each vertex with one closed fan or only
// open ones. Counts report.faces_detached and the first `original_vertices` vertices no face uses
// (report.isolated_vertices), and says in `sources` (when not null: only attributes need them)
// where each element came from. `uses` are the triangles' edge_uses when the caller has them
// (empty: computed here). Linear in the triangles. The positions and uses are taken so that they
// are freed as soon as the mesh has what it needs of them: the positions become the mesh's points
// array as they are, without a copy when their capacity is at least mesh_capacity(their count).
// The mesh has room for an eighth more of each element (what filling adds), so that adding the
// first patch does not copy every array into one twice its size.
Mesh assemble(std::vector<Point> positions, const std::vector<Triangle>& triangles,
              const std::vector<char>& detached, std::size_t original_vertices, LoadReport& report,
              MeshSources* sources, std::vector<EdgeUse> uses = {});

// The capacity assemble gives the mesh's arrays for `count` elements: a reader that knows how
// many positions it will read reserves this many, so that they become the mesh's without a copy.
std::size_t mesh_capacity(std::size_t count);

}  // namespace holefill::io
