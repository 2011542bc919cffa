#include "mesh_face_index.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include "flat_index_map.h"
#include "parallel_indices.h"

namespace holefill::detail {
namespace {

// The cells that pick the faces near the regions are about as large as the regions; a face
// whose box spans more than kMaxRegionCellsPerFace of them is filed without looking. The regions
// may be filed under at most kMaxMarkedCells cells (a region far larger than the others makes the
// cells larger), and a cell index needs at most kAxisBits bits on each axis.
constexpr double kMaxMarkedCells = 1 << 22;
constexpr double kMaxRegionCellsPerFace = 64;
constexpr int kAxisBits = 21;
constexpr double kMaxCellsPerAxis = 1 << kAxisBits;
// Faces filed by one task when the faces near the regions are filed on several threads: blocks
// of 65,536 split the 79,000 faces of a 1,000-edge hole's tube 83 : 17 between two threads.
constexpr int kFacesPerBlock = 1 << 14;

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

// The regions' mean extent (0 for none), accumulated so that it cannot overflow.
double mean_region_extent(const std::vector<Box>& regions) {
  double mean = 0.0;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    mean += ((regions[r].high - regions[r].low).max() - mean) / static_cast<double>(r + 1);
  }
  return mean;
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

// The regions filed under the cells of a grid over their bounding box, in a hash map (only the
// cells they touch take memory): whether a face's box overlaps one of them, found by testing only
// the regions in its cells. A dense array of coarse cells let most faces of a mesh through when
// the regions were spread out (a thousand small holes over a whole scan).
class RegionCells {
 public:
  // Nothing when the regions are too far apart for the arithmetic (coordinates near the largest
  // doubles): every face is then filed. The regions must outlive the result.
  static std::optional<RegionCells> of(const std::vector<Box>& regions) {
    RegionCells cells;
    for (const Box& region : regions) cells.bound_.add(region);
    const double mean_extent = mean_region_extent(regions);
    const Point span = cells.bound_.high - cells.bound_.low;
    cells.cell_ = mean_extent > 0.0 ? mean_extent : std::max(span.max(), 1.0);
    while (std::isfinite(cells.cell_) && !cells.fits(span, regions)) {
      cells.cell_ *= 2.0;
    }
    if (!std::isfinite(cells.cell_) || !cells.fits(span, regions)) return std::nullopt;
    cells.regions_ = &regions;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      cells.for_each_cell(regions[r], INFINITY, [&cells, r](std::uint64_t key) {
        int& first = cells.first_link_.find_or_insert(key, kNoLink);
        cells.links_.push_back({static_cast<int>(r), first});
        first = static_cast<int>(cells.links_.size()) - 1;
        return false;
      });
    }
    return cells;
  }

  // Whether `box` overlaps a region; true also for a box spanning too many cells to look.
  bool overlaps_region(const Box& box) const {
    if (!box.overlaps(bound_)) return false;
    return for_each_cell(box, kMaxRegionCellsPerFace, [this, &box](std::uint64_t key) {
      for (int link = first_link_.find(key, kNoLink); link != kNoLink; link = links_[link].next) {
        if ((*regions_)[static_cast<std::size_t>(links_[link].region)].overlaps(box)) return true;
      }
      return false;
    });
  }

 private:
  // Whether, at the current cell size, the span's cells can be numbered on every axis and the
  // regions mark few enough cells.
  bool fits(const Point& span, const std::vector<Box>& regions) {
    for (int axis = 0; axis < 3; ++axis) {
      const double n = std::floor(span[axis] / cell_) + 1.0;
      if (!(n <= kMaxCellsPerAxis)) return false;
      dims_[axis] = static_cast<std::uint64_t>(n);
    }
    double marked = 0.0;
    for (const Box& region : regions) {
      double cells = 1.0;
      for (int axis = 0; axis < 3; ++axis) {
        cells *=
            static_cast<double>(index(region.high[axis], axis) - index(region.low[axis], axis) + 1);
      }
      marked += cells;
    }
    return marked <= kMaxMarkedCells;
  }

  std::uint64_t index(double x, int axis) const {
    const double i = std::floor((x - bound_.low[axis]) / cell_);
    return static_cast<std::uint64_t>(std::clamp(i, 0.0, static_cast<double>(dims_[axis] - 1)));
  }

  // Calls visit(cell key) for the cells `box` touches (within the bound) until one returns true;
  // true then, or when the box spans more than `most` cells (none is visited then).
  template <class Visit>
  bool for_each_cell(const Box& box, double most, Visit&& visit) const {
    std::uint64_t low[3], high[3];
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
          // Below 2^63 - 1: never the hash set's empty key.
          if (visit((x << (2 * kAxisBits)) | (y << kAxisBits) | z)) return true;
        }
      }
    }
    return false;
  }

  static constexpr int kNoLink = -1;
  struct Link {
    int region, next;  // the next link of the same cell, or kNoLink
  };

  Box bound_;
  double cell_ = 1.0;
  std::uint64_t dims_[3] = {1, 1, 1};
  const std::vector<Box>* regions_ = nullptr;
  FlatIndexMap first_link_;  // cell key -> its first link
  std::vector<Link> links_;
};

}  // namespace

Box neighbourhood_of(const Mesh& mesh, const std::vector<VertexHandle>& loop) {
  Box box;
  for (const auto v : loop) box.add(mesh.point(v));
  return loop.empty() ? box : grown_by_extent(box);
}

MeshFaceIndex::MeshFaceIndex(const Mesh& mesh, const std::vector<Box>& regions, unsigned threads,
                             const Progress* progress)
    : mesh_(mesh), indexed_faces_(static_cast<int>(mesh.n_faces())) {
  enter_phase(progress, phase::kIndexingFaces);
  std::vector<Box> finite;
  std::copy_if(regions.begin(), regions.end(), std::back_inserter(finite), is_finite);
  // Patches' faces added later are filed in cells of a hole's neighbourhood's size, so that a
  // lookup across one neighbourhood touches a few cells.
  added_ = BoxBuckets(mean_region_extent(finite));
  if (!finite.empty()) file_faces_near(std::move(finite), threads, progress);
}

void MeshFaceIndex::file_faces_near(std::vector<Box> regions, unsigned threads,
                                    const Progress* progress) const {
  Part part{std::move(regions), false, FaceGrid({}), FaceGrid({})};
  part.everywhere = !std::all_of(part.regions.begin(), part.regions.end(), is_finite);
  if (!part.everywhere) {
    std::vector<std::pair<int, Box>> numbered;
    for (std::size_t r = 0; r < part.regions.size(); ++r) {
      numbered.emplace_back(static_cast<int>(r), part.regions[r]);
    }
    part.region_grid = FaceGrid(std::move(numbered));
  }
  std::optional<RegionCells> cells;
  if (!part.everywhere) cells = RegionCells::of(part.regions);
  part.everywhere = part.everywhere || !cells;
  // The faces in blocks (on `threads` threads), each block's in order, the blocks joined in order.
  const int faces = std::min(indexed_faces_, static_cast<int>(mesh_.n_faces()));
  std::vector<std::vector<std::pair<int, Box>>> blocks(
      static_cast<std::size_t>((faces + kFacesPerBlock - 1) / kFacesPerBlock));
  for_each_index(blocks.size(), threads, [&](std::size_t block) {
    if (is_cancelled(progress)) return;  // the blocks left are skipped: the index is dropped
    const int begin = static_cast<int>(block) * kFacesPerBlock;
    for (int f = begin; f < std::min(faces, begin + kFacesPerBlock); ++f) {
      const FaceHandle face(f);
      if (mesh_.has_face_status() && mesh_.status(face).deleted()) continue;
      const Box box = corners_box(mesh_, face);
      if (part.everywhere || cells->overlaps_region(box)) blocks[block].emplace_back(f, box);
    }
  });
  if (is_cancelled(progress)) return;
  std::vector<std::pair<int, Box>> boxes;
  std::size_t filed = 0;
  for (const auto& block : blocks) filed += block.size();
  boxes.reserve(filed);
  for (auto& block : blocks) {
    boxes.insert(boxes.end(), block.begin(), block.end());
    std::vector<std::pair<int, Box>>().swap(block);
  }
  part.faces = boxes.size();
  part.grid = FaceGrid(std::move(boxes), threads);
  parts_.push_back(std::move(part));
}

std::size_t MeshFaceIndex::filed_faces() const {
  std::size_t faces = 0;
  for (const Part& part : parts_) faces += part.faces;
  return faces;
}

const MeshFaceIndex::Part& MeshFaceIndex::part_holding(const Box& box) const {
  const bool finite = is_finite(box);
  for (const Part& part : parts_) {
    if (part.everywhere) return part;
    if (!finite) continue;
    for (const int r : part.region_grid.near(box)) {
      if (holds(part.regions[static_cast<std::size_t>(r)], box)) return part;
    }
  }
  file_faces_near({finite ? grown_by_extent(box) : box});
  return parts_.back();
}

MeshFaceIndex::MeshFaceIndex(const MeshFaceIndex& whole, const Box& region)
    : mesh_(whole.mesh_),
      indexed_faces_(whole.indexed_faces_),
      whole_(&whole),
      view_region_(region) {}

bool MeshFaceIndex::added_overlaps(const Box& box) const {
  std::vector<int> ids;
  return added_.append_overlapping(box, ids) > 0;
}

std::vector<int> MeshFaceIndex::near(const Box& box) const {
  if (whole_) {
    looked_up_.add(box);
    if (holds(view_region_, box)) return whole_->near(box);
    looked_outside_ = true;
    return {};
  }
  std::vector<int> ids = part_holding(box).grid.near(box);
  if (added_.append_overlapping(box, ids) > 0) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  return ids;
}

}  // namespace holefill::detail
