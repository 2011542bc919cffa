// Triangles by vertex index, their edges, and the Mesh they make once the repairs (soup_to_mesh)
// have made them consistent.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "holefill/io.h"
#include "huge_pages.h"
#include "two_threads.h"

namespace holefill::io {

using Triangle = std::array<int, 3>;

// One triangle's use of an undirected edge, kept in the run of the edge's smaller vertex
// (EdgeUses): the larger vertex, the triangle and its direction, in 8 bytes (three per triangle:
// the largest array while the repairs run; 16 bytes, then 12, before).
class EdgeUse {
 public:
  EdgeUse() = default;  // uninitialised, so that a block of uses costs nothing until written
  // `forward`: the triangle runs from the smaller vertex to the larger (triangle indices are
  // below 2^31).
  EdgeUse(int larger, int triangle, bool forward)
      : larger_(static_cast<std::uint32_t>(larger)),
        triangle_(static_cast<std::uint32_t>(triangle) | (forward ? kForward : 0)) {}

  int larger() const { return static_cast<int>(larger_); }
  int triangle() const { return static_cast<int>(triangle_ & ~kForward); }
  bool forward() const { return (triangle_ & kForward) != 0; }
  // The triangle was flipped: it runs along the edge the other way.
  void reverse() { triangle_ ^= kForward; }

 private:
  static constexpr std::uint32_t kForward = 0x80000000u;
  std::uint32_t larger_;
  std::uint32_t triangle_;  // the triangle's index, kForward when it runs forward
};
static_assert(sizeof(EdgeUse) == 8);

// Every use of an edge by a triangle, sorted by edge (smaller vertex, then larger), then by
// triangle; the uses of the edges whose smaller vertex is v are [start(v), start(v + 1)). They are
// kept in blocks of a huge page so that the mesh's arrays can grow while the uses they were made
// from are handed back (release_before).
class EdgeUses {
 public:
  EdgeUses() = default;
  // Made on `threads` threads (blocks of triangles counted and placed apart, the runs sorted in
  // blocks of vertices): the same uses on any number.
  explicit EdgeUses(const std::vector<Triangle>& triangles, unsigned threads = 1);

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  EdgeUse& operator[](std::size_t i) { return blocks_[i >> kBlockBits][i & kBlockMask]; }
  const EdgeUse& operator[](std::size_t i) const {
    return blocks_[i >> kBlockBits][i & kBlockMask];
  }
  // The vertices that may have uses: 0 .. vertex_bound() - 1.
  std::size_t vertex_bound() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t start(std::size_t vertex) const { return start_[vertex]; }

  // Calls visit(smaller, first, last) for the uses [first, last) of each edge, in edge order.
  template <class Visit>
  void for_each_edge(Visit&& visit) const {
    for_each_edge_in(0, vertex_bound(), visit);
  }
  // The same for the edges whose smaller vertex is in [first_vertex, last_vertex).
  template <class Visit>
  void for_each_edge_in(std::size_t first_vertex, std::size_t last_vertex, Visit&& visit) const {
    for (std::size_t v = first_vertex; v < last_vertex; ++v) {
      for (std::size_t i = start_[v]; i < start_[v + 1];) {
        std::size_t j = i + 1;
        while (j < start_[v + 1] && (*this)[j].larger() == (*this)[i].larger()) ++j;
        visit(static_cast<int>(v), i, j);
        i = j;
      }
    }
  }

  // Where `parts` blocks of vertices with about as many uses each begin, and the end: parts + 1
  // vertices from 0 to vertex_bound(), for work on the edges in blocks (for_each_edge_in).
  std::vector<std::size_t> vertex_parts(std::size_t parts) const;

  // Frees the blocks that hold only uses before `first`, which must not be read again.
  void release_before(std::size_t first);

 private:
  static constexpr int kBlockBits = 18;  // 256 K uses, 2 MB: one huge page
  static constexpr std::size_t kBlockMask = (std::size_t{1} << kBlockBits) - 1;
  void sort_runs_by_larger(std::size_t first_vertex, std::size_t last_vertex);

  std::vector<std::size_t> start_;
  std::vector<HugePageArray<EdgeUse>> blocks_;
  std::size_t size_ = 0;
};

// Where each element of an assembled mesh came from: the index of its input position (vertex)
// or input triangle (face). Both are empty when no triangle was detached: vertex i is then
// position i and face t triangle t (so the arrays the caller has per position and triangle serve
// as they are, where they were copied through the identity).
struct MeshSources {
  std::vector<int> vertex, face;
  bool identity() const { return vertex.empty() && face.empty(); }
};

// The mesh of `triangles` over `positions`. Triangles marked in `detached` are kept on their own
// copies of their corners (appended after the positions); the others must be consistent: every
// edge used at most twice, in opposite directions, and each vertex with one closed fan or only
// open ones. Counts report.faces_detached and the first `original_vertices` vertices no face uses
// (report.isolated_vertices), and says in `sources` (when not null: only attributes need them)
// where each element came from. `uses` are the triangles' edge uses when the caller has them
// (empty: made here). Linear in the triangles. Edges are numbered in the uses' order, an edge's
// first use (its lowest triangle) taking halfedge 2 e; a face's halfedge arrives at its triangle's
// first corner; a vertex's halfedge leaves it in the last triangle using it, or on a boundary.
// The positions, triangles, marks and uses are taken so that they are freed as soon as the mesh has
// what it needs of them: the positions become the mesh's points array as they are, without a copy
// when their capacity is at least mesh_capacity(their count); the triangles go before the mesh's
// edges are made, and the uses a block at a time as the edges are. The mesh has room for an eighth
// more of each element (what filling adds), so that adding the first patch does not copy every
// array into one twice its size. From `two_threads_from` faces on, independent parts run on two
// threads (two_threads.h), with the same mesh. `add_properties` (when given) adds properties to
// the mesh before it has elements: they get the room its arrays get, and their int and double
// arrays are on huge pages as its own are.
Mesh assemble(std::vector<Point> positions, std::vector<Triangle> triangles,
              std::vector<char> detached, std::size_t original_vertices, LoadReport& report,
              MeshSources* sources, EdgeUses uses = {},
              std::size_t two_threads_from = kTwoThreadsFrom,
              const std::function<void(Mesh&)>& add_properties = {});

// The capacity assemble gives the mesh's arrays for `count` elements: a reader that knows how
// many positions it will read reserves this many, so that they become the mesh's without a copy.
std::size_t mesh_capacity(std::size_t count);
// Reserves, on huge pages, room for `count` positions a reader is about to read: mesh_capacity's
// when they are the file's first (the mesh then takes them without a copy), else `count`.
void reserve_positions(std::vector<Point>& positions, std::size_t count, bool first_of_file);

}  // namespace holefill::io
