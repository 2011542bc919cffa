#include "repair_checks.h"

#include <atomic>

#include "../parallel_indices.h"
#include "huge_pages.h"

namespace holefill::io {
namespace {

// Whether `found` holds for some edge: each of `threads` blocks of vertices looks at its edges
// (until another block has found one).
template <class Found>
bool any_edge(const EdgeUses& uses, unsigned threads, Found&& found) {
  const std::vector<std::size_t> part = uses.vertex_parts(std::max(1u, threads));
  std::atomic<bool> any{false};
  detail::for_each_index(part.size() - 1, threads, [&](std::size_t p) {
    bool here = false;
    uses.for_each_edge_in(part[p], part[p + 1],
                          [&](int, std::size_t i, std::size_t j) { here = here || found(i, j); });
    if (here) any = true;
  });
  return any;
}

// The wedges (triangle t's corner c: 3 t + c) of a vertex joined into its fans, on several
// threads at once: a union-find whose roots are linked by compare-and-swap, the larger root under
// the smaller, so each set ends with its lowest wedge as root whatever the order of the joins.
class ConcurrentFans {
 public:
  explicit ConcurrentFans(std::size_t wedges) : parent_(huge_page_array<int>(wedges)) {}
  void make_set(int w) { parent_[w] = w; }
  // Joins the fans of wedges a and b; safe beside other joins.
  void join(int a, int b) {
    for (;;) {
      a = root(a), b = root(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      int expected = a;
      if (std::atomic_ref<int>(parent_[a]).compare_exchange_strong(expected, b)) return;
    }
  }
  // The root of w's fan (halving the path to it: every parent stays an ancestor).
  int root(int w) {
    for (;;) {
      const int p = std::atomic_ref<int>(parent_[w]).load(std::memory_order_relaxed);
      if (p == w) return w;
      const int up = std::atomic_ref<int>(parent_[p]).load(std::memory_order_relaxed);
      if (up != p) std::atomic_ref<int>(parent_[w]).store(up, std::memory_order_relaxed);
      w = up;
    }
  }

 private:
  HugePageArray<int> parent_;
};

}  // namespace

bool any_edge_run_the_same_way(const EdgeUses& uses, unsigned threads) {
  return any_edge(uses, threads, [&uses](std::size_t i, std::size_t j) {
    return j - i == 2 && uses[i].triangle() != uses[i + 1].triangle() &&
           uses[i].forward() == uses[i + 1].forward();
  });
}

bool any_non_manifold_edge(const EdgeUses& uses, unsigned threads) {
  return any_edge(uses, threads, [&uses](std::size_t i, std::size_t j) {
    return j - i > 2 || (j - i == 2 && uses[i].forward() == uses[i + 1].forward());
  });
}

// Each block of triangles, then each block of vertices' edges, then each block of triangles
// again: the wedges made sets, joined across the edges two triangles share, and each vertex's
// first fan claimed (another fan at a claimed vertex is the answer).
bool any_vertex_with_several_fans(const std::vector<Triangle>& triangles, const EdgeUses& uses,
                                  unsigned threads) {
  const std::size_t count = triangles.size(), blocks = std::max(1u, threads);
  auto block_begin = [&](std::size_t b) { return static_cast<int>(count * b / blocks); };
  auto wedge = [&triangles](int t, int vertex) {
    const auto& c = triangles[t];
    return 3 * t + (c[0] == vertex ? 0 : c[1] == vertex ? 1 : 2);
  };
  ConcurrentFans fans(3 * count);
  detail::for_each_index(blocks, threads, [&](std::size_t b) {
    for (int w = 3 * block_begin(b); w < 3 * block_begin(b + 1); ++w) fans.make_set(w);
  });
  const std::vector<std::size_t> part = uses.vertex_parts(blocks);
  detail::for_each_index(blocks, threads, [&](std::size_t p) {
    uses.for_each_edge_in(part[p], part[p + 1], [&](int smaller, std::size_t i, std::size_t j) {
      if (j - i != 2) return;
      const int a = uses[i].triangle(), b = uses[i + 1].triangle();
      for (const int v : {smaller, uses[i].larger()}) fans.join(wedge(a, v), wedge(b, v));
    });
  });
  auto first_fan = huge_page_array<int>(uses.vertex_bound());
  detail::for_each_index(blocks, threads, [&](std::size_t b) {
    const std::size_t vertices = uses.vertex_bound();
    std::fill(first_fan.get() + vertices * b / blocks,
              first_fan.get() + vertices * (b + 1) / blocks, -1);
  });
  std::atomic<bool> several{false};
  detail::for_each_index(blocks, threads, [&](std::size_t b) {
    for (int t = block_begin(b); t < block_begin(b + 1) && !several; ++t) {
      for (int c = 0; c < 3; ++c) {
        const int fan = fans.root(3 * t + c);
        int claimed = -1;
        std::atomic_ref<int> first(first_fan[triangles[t][c]]);
        if (!first.compare_exchange_strong(claimed, fan) && claimed != fan) several = true;
      }
    }
  });
  return several;
}

}  // namespace holefill::io
