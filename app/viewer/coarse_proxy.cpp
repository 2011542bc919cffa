#include "coarse_proxy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace holefill::viewer {
namespace {

// Cell coordinates take 21 bits each, so that three pack into one 64-bit key.
constexpr float kMaxCellsPerAxis = float{(1u << 21) - 1};

// The side of a grid cell that leaves about target / 2 occupied cells on the surface (a
// triangle mesh has about half as many vertices as triangles): the total area over that many
// squares, and never so fine that an axis needs more cells than a key holds.
float cell_side(const SurfaceArrays& full, std::size_t target) {
  double area = 0.0;
  for (std::size_t t = 0; t + 2 < full.triangles.size(); t += 3) {
    const glm::vec3& a = full.positions[full.triangles[t]];
    const glm::vec3& b = full.positions[full.triangles[t + 1]];
    const glm::vec3& c = full.positions[full.triangles[t + 2]];
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  const float extent =
      std::max({full.hi.x - full.lo.x, full.hi.y - full.lo.y, full.hi.z - full.lo.z, 1e-30f});
  const auto side = static_cast<float>(std::sqrt(area / std::max<double>(1.0, target / 2.0)));
  return std::max(side > 0.0f ? side : extent, extent / kMaxCellsPerAxis);
}

std::uint64_t cell_key(const glm::vec3& p, const glm::vec3& lo, float side) {
  std::uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const float cell = std::clamp(std::floor((p[axis] - lo[axis]) / side), 0.0f, kMaxCellsPerAxis);
    key = key << 21 | static_cast<std::uint64_t>(cell);
  }
  return key;
}

// A triangle of proxy vertices, turned so that its smallest index comes first (the same
// triangle from any corner, its orientation kept), packed into a sortable key, with the stage of
// a triangle it stands for.
struct ProxyTriangle {
  std::uint64_t key;
  std::uint8_t stage;
  bool operator<(const ProxyTriangle& other) const { return key < other.key; }
};

}  // namespace

SurfaceArrays coarse_proxy(const SurfaceArrays& full, std::size_t target) {
  SurfaceArrays proxy;
  proxy.lo = full.lo;
  proxy.hi = full.hi;
  const float side = cell_side(full, target);
  // Each vertex's cell, numbered in order of first use.
  std::unordered_map<std::uint64_t, std::uint32_t> cells;
  cells.reserve(target);
  std::vector<std::uint32_t> cell_of(full.positions.size());
  std::vector<float> members;
  const bool colored = full.colors.size() == full.positions.size();
  for (std::size_t v = 0; v < full.positions.size(); ++v) {
    const auto [it, added] = cells.try_emplace(cell_key(full.positions[v], full.lo, side),
                                               static_cast<std::uint32_t>(proxy.positions.size()));
    if (added) {
      proxy.positions.emplace_back(0.0f);
      proxy.normals.emplace_back(0.0f);
      members.push_back(0.0f);
      if (colored) proxy.colors.emplace_back(0.0f);
    }
    cell_of[v] = it->second;
    proxy.positions[it->second] += full.positions[v];
    if (v < full.normals.size()) proxy.normals[it->second] += full.normals[v];
    members[it->second] += 1.0f;
    if (colored) proxy.colors[it->second] += full.colors[v];
  }
  // A cell's normal is its vertices' (the surface's own shading); a proxy triangle turned
  // against its corners' normals is a fold the clustering made, and is left out.
  for (std::size_t c = 0; c < proxy.positions.size(); ++c) {
    proxy.positions[c] /= members[c];
    if (colored) proxy.colors[c] /= members[c];
    const float length = glm::length(proxy.normals[c]);
    proxy.normals[c] = length > 0.0f ? proxy.normals[c] / length : glm::vec3(0.0f, 0.0f, 1.0f);
  }
  // A triangle's key packs three proxy indices of 21 bits: a mesh whose vertices scatter over
  // more cells than that (isolated vertices everywhere) gets no proxy.
  constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << 21) - 1;
  if (proxy.positions.size() > kIndexMask) return {};
  std::vector<ProxyTriangle> kept;
  kept.reserve(full.triangles.size() / 3);
  for (std::size_t t = 0; t + 2 < full.triangles.size(); t += 3) {
    std::uint64_t c[3] = {cell_of[full.triangles[t]], cell_of[full.triangles[t + 1]],
                          cell_of[full.triangles[t + 2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
    const glm::vec3 area_normal = glm::cross(proxy.positions[c[1]] - proxy.positions[c[0]],
                                             proxy.positions[c[2]] - proxy.positions[c[0]]);
    if (!(glm::dot(area_normal, proxy.normals[c[0]] + proxy.normals[c[1]] + proxy.normals[c[2]]) >
          0.0f)) {
      continue;
    }
    const int first = c[0] < c[1] ? (c[0] < c[2] ? 0 : 2) : (c[1] < c[2] ? 1 : 2);
    const std::uint64_t key = c[first] << 42 | c[(first + 1) % 3] << 21 | c[(first + 2) % 3];
    const std::size_t face = t / 3;
    kept.push_back(
        {key, face < full.face_stages.size() ? full.face_stages[face] : std::uint8_t{0}});
  }
  std::sort(kept.begin(), kept.end());
  kept.erase(
      std::unique(kept.begin(), kept.end(),
                  [](const ProxyTriangle& a, const ProxyTriangle& b) { return a.key == b.key; }),
      kept.end());
  for (const ProxyTriangle& triangle : kept) {
    proxy.triangles.push_back(static_cast<std::uint32_t>(triangle.key >> 42));
    proxy.triangles.push_back(static_cast<std::uint32_t>(triangle.key >> 21 & kIndexMask));
    proxy.triangles.push_back(static_cast<std::uint32_t>(triangle.key & kIndexMask));
    proxy.face_stages.push_back(triangle.stage);
  }
  return proxy;
}

}  // namespace holefill::viewer
