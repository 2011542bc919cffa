#include "holefill/smooth.h"

#include <stdexcept>
#include <vector>

namespace holefill {
namespace {

Point umbrella(const Mesh& mesh, VertexHandle v) {
  Point sum(0.0, 0.0, 0.0);
  int count = 0;
  for (const auto q : mesh.vv_range(v)) {
    sum += mesh.point(q);
    ++count;
  }
  return count ? sum / count - mesh.point(v) : Point(0.0, 0.0, 0.0);
}

// Dense indices 0, 1, 2, ... for the mesh vertices a patch involves, in order of first insertion:
// an open-addressing table sized for the patch, not for the whole mesh.
class DenseIndex {
 public:
  explicit DenseIndex(std::size_t expected) {
    std::size_t size = 16;
    while (size < 2 * expected) size *= 2;
    keys_.assign(size, -1);
    values_.assign(size, -1);
  }
  // The dense index of `key`, the next free one when it is new.
  int insert(int key) {
    if (2 * (count_ + 1) > keys_.size()) grow();
    std::size_t slot = slot_of(key);
    if (keys_[slot] != key) {
      keys_[slot] = key;
      values_[slot] = static_cast<int>(count_++);
    }
    return values_[slot];
  }

 private:
  std::size_t slot_of(int key) const {
    const std::size_t mask = keys_.size() - 1;
    std::size_t slot = (static_cast<std::size_t>(key) * 0x9E3779B97F4A7C15ull) >> 20 & mask;
    while (keys_[slot] != -1 && keys_[slot] != key) slot = (slot + 1) & mask;
    return slot;
  }
  void grow() {
    std::vector<int> keys = std::move(keys_), values = std::move(values_);
    keys_.assign(2 * keys.size(), -1);
    values_.assign(2 * keys.size(), -1);
    for (std::size_t s = 0; s < keys.size(); ++s) {
      if (keys[s] == -1) continue;
      const std::size_t slot = slot_of(keys[s]);
      keys_[slot] = keys[s];
      values_[slot] = values[s];
    }
  }
  std::vector<int> keys_, values_;
  std::size_t count_ = 0;
};

}  // namespace

void smooth_patch(Mesh& mesh, const Patch& patch, const SmoothOptions& options,
                  const Progress* progress) {
  if (options.method != SmoothMethod::Umbrella) {
    throw std::invalid_argument(
        "smooth_patch smooths with the umbrella operator only (fairing: fair_patch)");
  }
  // The patch's vertices and their neighbours copied once into flat arrays (neighbours in the
  // mesh's circulation order, so the sums are the same as over the mesh), so that the iterations
  // touch no half-edge structure: linear in the patch size with a small constant.
  const std::size_t moving = patch.new_vertices.size();
  DenseIndex local(8 * moving + 16);
  std::vector<Point> position;
  auto index_of = [&](VertexHandle v) {
    const int index = local.insert(v.idx());
    if (index == static_cast<int>(position.size())) position.push_back(mesh.point(v));
    return index;
  };
  std::vector<int> own_index;  // of each new vertex, in patch.new_vertices' order
  for (const auto v : patch.new_vertices) own_index.push_back(index_of(v));
  std::vector<int> neighbour_start{0}, neighbours;
  for (const auto v : patch.new_vertices) {
    for (const auto q : mesh.vv_range(v)) neighbours.push_back(index_of(q));
    neighbour_start.push_back(static_cast<int>(neighbours.size()));
  }
  std::vector<Point> moved(moving);
  for (int it = 0; it < options.iterations; ++it) {
    if (is_cancelled(progress)) return;
    for (std::size_t i = 0; i < moving; ++i) {
      const int begin = neighbour_start[i], end = neighbour_start[i + 1];
      const Point& p = position[own_index[i]];
      Point sum(0.0, 0.0, 0.0);
      for (int j = begin; j < end; ++j) sum += position[neighbours[j]];
      const Point umbrella = end > begin ? sum / (end - begin) - p : Point(0.0, 0.0, 0.0);
      moved[i] = p + options.step * umbrella;
    }
    for (std::size_t i = 0; i < moving; ++i) position[own_index[i]] = moved[i];
  }
  for (std::size_t i = 0; i < moving; ++i) {
    mesh.set_point(patch.new_vertices[i], position[own_index[i]]);
  }
}

double umbrella_energy(const Mesh& mesh, const Patch& patch) {
  double energy = 0.0;
  for (const auto v : patch.new_vertices) energy += umbrella(mesh, v).sqrnorm();
  return energy;
}

}  // namespace holefill
