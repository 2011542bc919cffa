// The full search on several threads. Rows run bottom-up: cell (i, k) needs (i, m), m < k, from
// its own row and (m, k), m > i, from the rows below, so row i can follow row i + 1 cell by cell.
// The rows are taken in strips of kStripRows: a thread takes the next strip up and solves it
// column by column, each column's cells bottom-up, once the strip below has finished that column
// (RowWavefront). A column's keys, areas and normals then are read from the cache once for the
// strip's cells instead of once per cell (the column tables are larger than the cache), and the
// other thread writes into a column's cache lines only where its strip begins, instead of into
// every other cell's line. Each cell is computed exactly as on one thread, from the same inputs,
// so the triangulation does not depend on the number of threads (tests compare).
#include "full_search.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <memory>
#include <system_error>
#include <thread>
#include <vector>

#include "available_cores.h"
#include "bound_scan.h"
#include "dp_step.h"
#include "row_wavefront.h"
#include "table_budget.h"

namespace holefill::detail {
namespace {

// Below this many edges a search takes under a few milliseconds on one core, and starting and
// feeding threads costs more than it saves (bench/NOTEBOOK.md).
constexpr int kParallelMinEdges = 120;

// Rows per strip: a strip reads each column's tables once for this many cells, and the strip's own
// rows (the left sides of its candidates) stay in the second-level cache up to thousands of edges.
// At 2,000 edges 8 rows took 3.3-3.5 s on one thread, 16 rows 3.0-3.1 s, single rows 4.6-5.3 s;
// at 500 edges the three are the same within the machine's noise (bench/NOTEBOOK.md).
constexpr int kStripRows = 16;

// Cell (i, k), 0 <= i < k < n, of the triangular tables, stored row by row (row i holds
// k = i+1 ... n-1) or column by column (column k holds i = 0 ... k-1).
std::size_t cell_count(int n) {
  return static_cast<std::size_t>(n) * static_cast<std::size_t>(n - 1) / 2;
}
std::size_t row_start(int n, int i) {
  const std::size_t row = static_cast<std::size_t>(i);
  return row * static_cast<std::size_t>(n) - row * (row + 1) / 2;
}
std::size_t column_start(int k) {
  const std::size_t column = static_cast<std::size_t>(k);
  return column * (column - 1) / 2;
}

}  // namespace

std::size_t table_bytes(int n, bool keep_normals) {
  const std::size_t per_cell = 2 * sizeof(std::uint64_t) + sizeof(double) + sizeof(float) +
                               sizeof(std::uint16_t) + (keep_normals ? sizeof(Point) : 0);
  return cell_count(n) * per_cell + cell_count(n) / 8;  // and a bit per cell: forbidden chords
}

namespace {

// The area rounded down to a float: a lower bound that fits in half the space.
float area_lower_bound(double area) {
  const float rounded = static_cast<float>(area);
  return static_cast<double>(rounded) <= area ? rounded : std::nextafter(rounded, 0.0f);
}

constexpr std::uint16_t kNoApex = 0xFFFF;  // apex of an infeasible cell

// The dynamic program's tables, in 30 bytes per cell: by rows the value (key and area) and the
// apex; by columns the key again and a lower bound of the area, so that the apex loop reads both
// sides sequentially; a bit for forbidden chords. Weights with dihedral angles also keep each
// cell's triangle normal by columns (24 bytes more): a candidate's dihedral angle across its
// side (m, k) reads it instead of computing it again from the apex, a tenth of the search.
struct Tables {
  // The cells' arrays are not cleared here: each cell (i, k), k >= i + 2, is written by the thread
  // solving it before it is read, so that their pages are first touched on the solving threads
  // (clearing them, 15 MB at 1,000 edges, was a serial 4 % of the search). Only the polygon's
  // edges, the sides of the smallest cells, are set here.
  Tables(const HolePolygon& polygon, bool keep_normals)
      : n(static_cast<int>(polygon.points.size())),
        row_key(std::make_unique_for_overwrite<std::uint64_t[]>(cell_count(n))),
        column_key(std::make_unique_for_overwrite<std::uint64_t[]>(cell_count(n))),
        row_area(std::make_unique_for_overwrite<double[]>(cell_count(n))),
        column_area(std::make_unique_for_overwrite<float[]>(cell_count(n))),
        apex(std::make_unique_for_overwrite<std::uint16_t[]>(cell_count(n))),
        forbidden(cell_count(n), false),
        column_normal(keep_normals ? cell_count(n) : 0),
        row_starts(static_cast<std::size_t>(n)) {
    for (int i = 0; i < n; ++i) row_starts[i] = row_start(n, i);
    for (int i = 0; i + 1 < n; ++i) {
      const std::size_t cell = row_index(i, i + 1), column = column_start(i + 1) + i;
      row_key[cell] = column_key[column] = 0;
      row_area[cell] = 0.0;
      column_area[column] = 0.0f;
      apex[cell] = 0;  // never read
    }
    for (const Point& point : polygon.points) {
      x.push_back(point[0]);
      y.push_back(point[1]);
      z.push_back(point[2]);
    }
    for (const auto& [a, b] : polygon.forbidden_chords) {
      if (a == b || std::min(a, b) < 0 || std::max(a, b) >= n) continue;  // not a chord
      forbidden[row_index(std::min(a, b), std::max(a, b))] = true;
    }
  }

  // Where cell (i, k) lies in the row-by-row tables.
  std::size_t row_index(int i, int k) const {
    return row_starts[static_cast<std::size_t>(i)] + static_cast<std::size_t>(k - i - 1);
  }

  void store(int i, int k, const CellBest& best) {
    const std::size_t cell = row_index(i, k), column = column_start(k) + i;
    const bool feasible = best.apex >= 0;
    row_key[cell] = column_key[column] = feasible ? best.value.key : weight_key::kInfeasible;
    row_area[cell] = feasible ? best.value.area : INFINITY;
    column_area[column] = feasible ? area_lower_bound(best.value.area) : INFINITY;
    apex[cell] = feasible ? static_cast<std::uint16_t>(best.apex) : kNoApex;
  }

  int n;
  std::unique_ptr<std::uint64_t[]> row_key, column_key;
  std::unique_ptr<double[]> row_area;
  std::unique_ptr<float[]> column_area;
  std::unique_ptr<std::uint16_t[]> apex;
  std::vector<bool> forbidden;          // written before the threads start
  std::vector<Point> column_normal;     // of feasible cells, when the weight needs them
  std::vector<std::size_t> row_starts;  // row_start(n, i), looked up rather than recomputed
  std::vector<double> x, y, z;          // the points' coordinates, for the bound scan
};

// Solves strips of rows of the tables; one per thread. With kPrune a candidate is skipped when the
// lane-wise maximum of its two sides' keys already exceeds the best key (a lower bound of its
// value, weight_key::lane_max) or ties it with no smaller area, then as soon as a partial value
// cannot beat the best (try_apex). The values computed are the same either way, so the result is
// the plain loop's (kPrune = false), and tests check it.
template <bool kPrune, class Weight>
class StripSolver {
 public:
  StripSolver(const HolePolygon& polygon, const Weight& weight, Tables& tables)
      : polygon_(polygon),
        weight_(weight),
        t_(tables),
        // Sized for the tallest strip here, on the calling thread: solve_strip runs on helper
        // threads, where an allocation that failed would end the process (nothing there can
        // catch it and stop the strips waiting for this one).
        strip_normals_(static_cast<std::size_t>(kStripRows) * static_cast<std::size_t>(tables.n)),
        first_within_bound_(fastest_bound_scan()) {}

  // Rows lowest ... highest (highest <= n - 3, at most kStripRows of them), column by column:
  // cells (r, k) for r + 2 <= k, from the highest row down, once the rows below the strip have
  // finished column k. Allocates nothing.
  void solve_strip(int lowest, int highest, RowWavefront& wavefront) {
    const int n = t_.n;
    assert(highest - lowest + 1 <= kStripRows);
    strip_lowest_ = lowest;
    int below_finished = -1;
    const bool strip_below = highest + 1 <= n - 3;
    for (int k = lowest + 2; k < n; ++k) {
      if (strip_below && k - highest > 2 && k > below_finished) {
        below_finished = wavefront.wait_for(highest + 1, k);
      }
      for (int i = std::min(highest, k - 2); i >= lowest; --i) solve_cell(i, k);
      wavefront.publish(lowest, k);
    }
  }

 private:
  // Where the sides of one cell's candidates lie (best_apex).
  struct Sides {
    std::size_t left, right;
  };

  // Whether keys carry angle lanes, so that the bound rules out apexes; the area weight's hold
  // only degenerate counts, and scanning them would cost more than it skips.
  static constexpr bool kKeysBound = Weight::kUsesDihedral || Weight::kUsesMinAngle;

  void solve_cell(int i, int k) {
    const int n = t_.n;
    if (t_.forbidden[t_.row_index(i, k)] && !(i == 0 && k == n - 1)) {
      t_.store(i, k, CellBest{});
      return;
    }
    current_row_ = i;
    row_normal_ = strip_normals_.data() +
                  static_cast<std::size_t>(i - strip_lowest_) * static_cast<std::size_t>(n);
    const CellBest best = best_apex(i, k);
    t_.store(i, k, best);
    if (best.apex >= 0 && Weight::kUsesDihedral) {
      row_normal_[k] =
          unit_normal(polygon_.points[i], polygon_.points[best.apex], polygon_.points[k]);
      t_.column_normal[column_start(k) + static_cast<std::size_t>(i)] = row_normal_[k];
    }
  }

  CellBest best_apex(int i, int k) const {
    // Side (i, m) at row index `left + m`, side (m, k) at column index `right + m` (unsigned:
    // `left` wraps below zero on row 0, and adding m brings it back).
    const Sides sides{t_.row_starts[static_cast<std::size_t>(i)] - static_cast<std::size_t>(i + 1),
                      column_start(k)};
    CellBest best;
    if constexpr (!kPrune) {
      for (int m = i + 1; m < k; ++m) try_apex(i, m, k, sides, best);
      return best;
    }
    // The apexes of the cells below and to the left are often this cell's best too (each in
    // about a third of the cells, not always the same third): tried first, they let the bound
    // discard most other apexes at once.
    const int seed = k - i > 2 ? t_.apex[t_.row_index(i + 1, k)] : kNoApex;
    if (seed != kNoApex) try_apex(i, seed, k, sides, best);
    const int seed2 = k - i > 2 ? t_.apex[t_.row_index(i, k - 1)] : kNoApex;
    if (seed2 != kNoApex && seed2 != seed) try_apex(i, seed2, k, sides, best);
    const Point& origin = polygon_.points[i];
    const Point to_k = polygon_.points[k] - origin;
    const ApexBase base{{origin[0], origin[1], origin[2]}, {to_k[0], to_k[1], to_k[2]}};
    for (int m = i + 1; m < k; ++m) {
      if constexpr (kKeysBound) {
        // Most apexes fail the bounds, in long runs: skip them four at a time.
        const std::size_t left = sides.left + static_cast<std::size_t>(m);
        const std::size_t right = sides.right + static_cast<std::size_t>(m);
        const ApexRun run{t_.row_key.get() + left,  t_.column_key.get() + right,
                          t_.row_area.get() + left, t_.column_area.get() + right,
                          t_.x.data() + m,          t_.y.data() + m,
                          t_.z.data() + m,          k - m};
        m += first_within_bound_(run, base, BestSoFar{best.value.key, best.value.area});
        if (m >= k) break;
      }
      if (m != seed && m != seed2) try_apex(i, m, k, sides, best);
    }
    return best;
  }

  void try_apex(int i, int m, int k, const Sides& sides, CellBest& best) const {
    const std::size_t left_cell = sides.left + static_cast<std::size_t>(m);
    const std::size_t right_column = sides.right + static_cast<std::size_t>(m);
    const std::uint64_t left = t_.row_key[left_cell], right = t_.column_key[right_column];
    if constexpr (kPrune) {
      const std::uint64_t bound = weight_key::lane_max(left, right);
      if (bound > best.value.key) return;
      if (bound == best.value.key &&
          best.excludes(bound, t_.row_area[left_cell] + t_.column_area[right_column], m)) {
        return;
      }
    } else {
      if (left == weight_key::kInfeasible || right == weight_key::kInfeasible) return;
    }
    const auto normal_across = [this](int a, int b) -> const Point& {
      return this->normal_across(a, b);
    };
    detail::try_apex<kPrune>(
        weight_, polygon_, i, m, k, WeightValue{left, t_.row_area[left_cell]},
        SideValue{right, t_.column_area[right_column], &t_.row_area[t_.row_index(m, k)]},
        normal_across, best);
  }

  // Normal of the triangle chosen for sub-polygon (a, b), or of the mesh face across (a, b).
  // The current row's are read from the strip's copy in row order, where the row reads them over
  // and over; others from the table, in column order as the apex loop walks them.
  const Point& normal_across(int a, int b) const {
    if (b == a + 1) return polygon_.outside_normals[a];
    if (a == current_row_) return row_normal_[b];
    return t_.column_normal[column_start(b) + static_cast<std::size_t>(a)];
  }

  const HolePolygon& polygon_;
  const Weight& weight_;
  Tables& t_;
  std::vector<Point> strip_normals_;  // row by row: of cell (r, k) at (r - strip_lowest_) * n + k
  int strip_lowest_ = 0;
  Point* row_normal_ = nullptr;  // row_normal_[k]: of cell (current_row_, k), in strip_normals_
  int current_row_ = -1;
  BoundScan first_within_bound_;
};

// Helper threads that the searches running at the same time share: one fewer than the cores in
// all, so that several searches at once (fill_holes plans holes on every core) do not
// oversubscribe the machine.
class HelperThreads {
 public:
  explicit HelperThreads(int wanted) {
    int spare = spare_.load();
    do {
      count_ = std::clamp(wanted, 0, spare);
    } while (!spare_.compare_exchange_weak(spare, spare - count_));
  }
  ~HelperThreads() { spare_ += count_; }
  HelperThreads(const HelperThreads&) = delete;
  HelperThreads& operator=(const HelperThreads&) = delete;
  int count() const { return count_; }

 private:
  static inline std::atomic<int> spare_{static_cast<int>(available_cores()) - 1};
  int count_ = 0;
};

template <bool kPrune, class Weight>
std::optional<PolygonTriangulation> solve(const HolePolygon& polygon, const Weight& weight,
                                          int threads, const TriangulateOptions& options) {
  const TableBudget::Lease lease = full_search_table_budget().acquire(
      table_bytes(static_cast<int>(polygon.points.size()), Weight::kUsesDihedral),
      [&] { return cancelled(options); });
  if (!lease.held()) return std::nullopt;  // cancelled while waiting for room
  Tables tables(polygon, Weight::kUsesDihedral);
  const int n = tables.n;
  RowWavefront wavefront(n);
  std::vector<StripSolver<kPrune, Weight>> solvers(
      static_cast<std::size_t>(threads), StripSolver<kPrune, Weight>(polygon, weight, tables));
  std::atomic<int> next_strip{0};  // counted from the bottom
  // A cancel stops the taking of strips; a strip once taken is finished, since the strips above
  // it that were taken before the cancel wait for it.
  auto solve_strips = [&](StripSolver<kPrune, Weight>& solver) {
    while (!cancelled(options)) {
      const int highest = n - 3 - kStripRows * next_strip++;
      if (highest < 0) break;
      solver.solve_strip(std::max(0, highest - kStripRows + 1), highest, wavefront);
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (int t = 1; t < threads; ++t) {
      try {
        helpers.emplace_back(solve_strips, std::ref(solvers[static_cast<std::size_t>(t)]));
      } catch (const std::system_error&) {
        break;  // no more threads to be had: strips are taken as they come, fewer threads suffice
      }
    }
    solve_strips(solvers[0]);
  }
  if (cancelled(options) || tables.apex[tables.row_index(0, n - 1)] == kNoApex) return std::nullopt;

  PolygonTriangulation result;
  result.triangles =
      trace_triangles(n, [&](int i, int k) { return tables.apex[tables.row_index(i, k)]; });
  result.quality = evaluate_triangulation(polygon, result.triangles);
  return result;
}

}  // namespace

std::optional<PolygonTriangulation> full_search(const HolePolygon& polygon,
                                                const TriangulateOptions& options) {
  const int n = static_cast<int>(polygon.points.size());
  const int strips = std::max(1, (n - 2 + kStripRows - 1) / kStripRows);
  const bool automatic = options.threads == 0;
  // Automatic threads: every core this process may run on, shared with the searches running at
  // the same time, the scheduling left to the system. A guess at what other processes leave
  // free (the load average lags by a minute: a search started on a just-quiet machine ran on one
  // thread) would only hide the cores; a caller that knows the machine is busy asks for fewer.
  const int wanted = automatic ? (n < kParallelMinEdges ? 1 : static_cast<int>(available_cores()))
                               : static_cast<int>(std::min<unsigned>(options.threads, strips));
  // Threads asked for explicitly are the caller's business; automatic ones share the cores.
  const HelperThreads helpers(automatic ? wanted - 1 : 0);
  const int threads = std::clamp(automatic ? 1 + helpers.count() : wanted, 1, strips);
  return with_weight(options, [&](const auto& weight) {
    return options.prune ? solve<true>(polygon, weight, threads, options)
                         : solve<false>(polygon, weight, threads, options);
  });
}

}  // namespace holefill::detail
