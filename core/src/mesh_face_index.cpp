#include "mesh_face_index.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

namespace holefill::detail {
namespace {

// The coarse grid that picks the faces near the regions has at most this many cells; a face whose
// box spans more than kMaxCellsPerFace of them is filed without looking.
constexpr double kMaxCoarseCells = 1 << 22;
constexpr double kMaxCellsPerFace = 64;

// Finite coordinates, low <= high on every axis (a NaN, an infinity or the empty Box fail).
bool is_finite(const Box& box) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!std::isfinite(box.low[axis]) || !std::isfinite(box.high[axis]) ||
        !(box.low[axis] <= box.high[axis])) {
      return false;
    }
  }
  return true;
}

bool holds(const Box& region, const Box& box) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!(region.low[axis] <= box.low[axis] && box.high[axis] <= region.high[axis])) return false;
  }
  return true;
}

Box grown_by_extent(Box box) {
  box.grow((box.high - box.low).max());
  return box;
}

Box corners_box(const Mesh& mesh, FaceHandle face) {
  Box box;
  const HalfedgeHandle first = mesh.halfedge_handle(face);
  HalfedgeHandle h = first;
  do {
    box.add(mesh.point(mesh.to_vertex_handle(h)));
    h = mesh.next_halfedge_handle(h);
  } while (h != first);
  return box;
}

// Which cells of a coarse grid over the regions' bounding box the regions touch: a quick,
// conservative test of whether a face's box may overlap one of them (a face it lets through
// only costs a grid entry).
class RegionCells {
 public:
  // Nothing when the regions are too far apart for the arithmetic (coordinates near the largest
  // doubles): every face is then filed.
  static std::optional<RegionCells> of(const std::vector<Box>& regions) {
    RegionCells cells;
    double mean_extent = 0.0;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      cells.bound_.add(regions[r]);
      mean_extent += ((regions[r].high - regions[r].low).max() - mean_extent) / double(r + 1);
    }
    const Point span = cells.bound_.high - cells.bound_.low;
    cells.cell_ = mean_extent > 0.0 ? mean_extent : std::max(span.max(), 1.0);
    double count = cells.counts(span);
    while (count > kMaxCoarseCells && std::isfinite(count) && std::isfinite(cells.cell_)) {
      cells.cell_ *= std::max(2.0, std::cbrt(count / kMaxCoarseCells));
      count = cells.counts(span);
    }
    if (!std::isfinite(count) || !std::isfinite(cells.cell_) || count > kMaxCoarseCells) {
      return std::nullopt;
    }
    cells.marked_.assign(static_cast<std::size_t>(count), 0);
    for (const Box& region : regions) {
      cells.for_each_cell(region, INFINITY, [&cells](std::size_t c) {
        cells.marked_[c] = 1;
        return false;
      });
    }
    return cells;
  }

  bool may_touch(const Box& box) const {
    if (!box.overlaps(bound_)) return false;
    return for_each_cell(box, kMaxCellsPerFace, [this](std::size_t c) { return marked_[c] != 0; });
  }

 private:
  // The grid's dimensions for `span` at the current cell size, and their product.
  double counts(const Point& span) {
    double count = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double n = std::floor(span[axis] / cell_) + 1.0;
      dims_[axis] = std::isfinite(n) ? static_cast<std::size_t>(std::min(n, kMaxCoarseCells)) : 1;
      count *= n;
    }
    return count;
  }

  std::size_t index(double x, int axis) const {
    const double i = std::floor((x - bound_.low[axis]) / cell_);
    return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(dims_[axis] - 1)));
  }

  // Calls visit(cell) for the cells `box` touches (within the bound) until one returns true;
  // true then, or when the box spans more than `most` cells (none is visited then).
  template <class Visit>
  bool for_each_cell(const Box& box, double most, Visit&& visit) const {
    std::size_t low[3], high[3];
    double cells = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      low[axis] = index(box.low[axis], axis);
      high[axis] = index(box.high[axis], axis);
      cells *= static_cast<double>(high[axis] - low[axis] + 1);
    }
    if (cells > most) return true;
    for (auto x = low[0]; x <= high[0]; ++x) {
      for (auto y = low[1]; y <= high[1]; ++y) {
        for (auto z = low[2]; z <= high[2]; ++z) {
          if (visit((x * dims_[1] + y) * dims_[2] + z)) return true;
        }
      }
    }
    return false;
  }

  Box bound_;
  double cell_ = 1.0;
  std::size_t dims_[3] = {1, 1, 1};
  std::vector<char> marked_;
};

}  // namespace

Box neighbourhood_of(const Mesh& mesh, const std::vector<VertexHandle>& loop) {
  Box box;
  for (const auto v : loop) box.add(mesh.point(v));
  return loop.empty() ? box : grown_by_extent(box);
}

MeshFaceIndex::MeshFaceIndex(const Mesh& mesh, const std::vector<Box>& regions)
    : mesh_(mesh), indexed_faces_(static_cast<int>(mesh.n_faces())) {
  std::vector<Box> finite;
  std::copy_if(regions.begin(), regions.end(), std::back_inserter(finite), is_finite);
  if (!finite.empty()) file_faces_near(std::move(finite));
}

void MeshFaceIndex::file_faces_near(std::vector<Box> regions) const {
  Part part{std::move(regions), false, FaceGrid({})};
  part.everywhere = !std::all_of(part.regions.begin(), part.regions.end(), is_finite);
  std::optional<RegionCells> cells;
  if (!part.everywhere) cells = RegionCells::of(part.regions);
  part.everywhere = part.everywhere || !cells;
  std::vector<std::pair<int, Box>> boxes;
  for (const auto f : mesh_.faces()) {
    if (f.idx() >= indexed_faces_) break;
    const Box box = corners_box(mesh_, f);
    if (part.everywhere || cells->may_touch(box)) boxes.emplace_back(f.idx(), box);
  }
  part.grid = FaceGrid(std::move(boxes));
  parts_.push_back(std::move(part));
}

const MeshFaceIndex::Part& MeshFaceIndex::part_holding(const Box& box) const {
  const bool finite = is_finite(box);
  for (const Part& part : parts_) {
    if (part.everywhere) return part;
    if (!finite) continue;
    for (const Box& region : part.regions) {
      if (holds(region, box)) return part;
    }
  }
  file_faces_near({finite ? grown_by_extent(box) : box});
  return parts_.back();
}

std::vector<int> MeshFaceIndex::near(const Box& box) const {
  std::vector<int> ids = part_holding(box).grid.near(box);
  bool added = false;
  for (const auto& [id, entry] : added_) {
    if (!entry.overlaps(box)) continue;
    ids.push_back(id);
    added = true;
  }
  if (added) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  return ids;
}

}  // namespace holefill::detail
