#include "patch_intersections.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "exact_triangle_intersection.h"
#include "parallel_indices.h"
#include "segment_box_tree.h"
#include "triangle_intersection.h"

namespace holefill::detail {
namespace {

// A power of two that brings coordinates up to `magnitude` to at most 2, so that the products
// of the intersection tests cannot overflow (and, exact, changes no answer).
double scale_for(double magnitude) {
  if (!(magnitude > 0.0) || !std::isfinite(magnitude)) return 1.0;
  return std::ldexp(1.0, -std::clamp(std::ilogb(magnitude), -1000, 1000));
}

// Patch triangles scanned by one task when a patch is checked on several threads (a millisecond
// or two of work: small enough that the last blocks leave no thread long alone, and that a
// triangulated hole of a thousand edges is scanned on two); faces gathered or scaled by one task
// before.
constexpr int kTrianglesPerBlock = 512;
constexpr std::size_t kCandidatesPerBlock = 16384;

Box box_of_corners(const std::array<Point, 3>& corners) {
  Box box;
  for (const auto& p : corners) box.add(p);
  return box;
}

// A cancel is looked at once per this many triangles, faces or chords: well under a millisecond
// of work each, and a load of an atomic is nothing beside it.
constexpr int kBetweenCancelChecks = 1024;

bool stop_at(std::size_t i, const Progress* progress) {
  return i % kBetweenCancelChecks == 0 && is_cancelled(progress);
}

}  // namespace

namespace {

// What a patch's triangles are compared with: the patch's triangles first, then the faces of the
// mesh near them, with their boxes and their triangles scaled for the floating-point test.
struct Candidates {
  std::vector<FaceHandle> faces;  // of the mesh's faces (after the patch's triangles)
  std::vector<std::pair<int, Box>> boxes;
  std::vector<std::optional<Triangle3>> scaled;
};

std::size_t blocks_of(std::size_t count, std::size_t per_block) {
  return (count + per_block - 1) / per_block;
}

// The candidates, gathered and scaled in blocks on `threads` threads, in order (the same on any
// number); nothing when `progress` was cancelled meanwhile. The arrays are sized before they are
// filled (counted first, then written at each block's place), and the mesh faces' corners read
// again rather than kept: after each stage of a large hole they hold hundreds of thousands of
// entries, and on this VM faulting in fresh pages was a quarter of the checks.
std::optional<Candidates> candidates_of(const Mesh& mesh, const Mesh& others,
                                        const std::vector<std::array<Point, 3>>& triangles,
                                        const PatchFaceSet* in_patch,
                                        const std::vector<int>* near_reach, const Box& reach,
                                        unsigned threads, const Progress* progress) {
  Candidates c;
  c.faces.resize(triangles.size());
  for (const auto& t : triangles) {
    c.boxes.emplace_back(static_cast<int>(c.boxes.size()), box_of_corners(t));
  }
  const std::size_t count = near_reach ? near_reach->size() : mesh.n_faces();
  const auto other_face = [&](std::size_t i) -> std::optional<std::pair<FaceHandle, Box>> {
    const FaceHandle f(near_reach ? (*near_reach)[i] : static_cast<int>(i));
    if (!near_reach && mesh.has_face_status() && mesh.status(f).deleted()) return std::nullopt;
    if ((in_patch && in_patch->contains(f)) || others.valence(f) != 3) return std::nullopt;
    const Box box = box_of(others, f);
    if (!box.overlaps(reach)) return std::nullopt;
    return std::pair(f, box);
  };
  const std::size_t blocks = blocks_of(count, kCandidatesPerBlock);
  std::vector<std::size_t> block_start(blocks + 1, 0);
  for_each_block(count, kCandidatesPerBlock, threads,
                 [&](std::size_t begin, std::size_t end, std::size_t block) {
                   for (std::size_t i = begin; i < end; ++i) {
                     if (stop_at(i, progress)) return;
                     if (other_face(i)) ++block_start[block + 1];
                   }
                 });
  if (is_cancelled(progress)) return std::nullopt;
  block_start[0] = triangles.size();
  for (std::size_t block = 0; block < blocks; ++block) block_start[block + 1] += block_start[block];
  c.faces.resize(block_start.back());
  c.boxes.resize(block_start.back());
  for_each_block(count, kCandidatesPerBlock, threads,
                 [&](std::size_t begin, std::size_t end, std::size_t block) {
                   std::size_t at = block_start[block];
                   for (std::size_t i = begin; i < end; ++i) {
                     if (const auto found = other_face(i)) {
                       c.faces[at] = found->first;
                       c.boxes[at] = {static_cast<int>(at), found->second};
                       ++at;
                     }
                   }
                 });
  double magnitude = 0.0;
  for (const auto& [id, box] : c.boxes) magnitude = std::max(magnitude, box.magnitude());
  const double scale = scale_for(magnitude);
  c.scaled.resize(c.faces.size());
  for_each_block(c.faces.size(), kCandidatesPerBlock, threads,
                 [&](std::size_t begin, std::size_t end, std::size_t) {
                   for (std::size_t o = begin; o < end; ++o) {
                     if (o < triangles.size()) {
                       c.scaled[o] = triangle_from(triangles[o], scale);
                       continue;
                     }
                     auto fv = others.cfv_iter(c.faces[o]);
                     c.scaled[o] = triangle_from(
                         {others.point(*fv), others.point(*++fv), others.point(*++fv)}, scale);
                   }
                 });
  return c;
}

}  // namespace

std::vector<IntersectingPair> triangle_intersections(
    const Mesh& mesh, const std::vector<std::array<Point, 3>>& triangles,
    const PatchFaceSet* in_patch, const MeshFaceIndex* around, bool exact_too,
    const Progress* progress) {
  if (triangles.empty()) return {};
  // The index may number the faces of another mesh than the patch's (a hole filled apart from the
  // mesh, patch_apart.h): the other triangles are read there, and none of them is the patch's.
  const Mesh& others = around ? around->mesh() : mesh;
  if (&others != &mesh) in_patch = nullptr;
  Box reach;
  for (const auto& t : triangles) reach.add(box_of_corners(t));
  reach.grow(1e-9 * (reach.high - reach.low).max());
  const std::vector<int> near_reach = around ? around->near(reach) : std::vector<int>{};
  const unsigned threads = around ? around->threads() : 1;
  auto candidates = candidates_of(mesh, others, triangles, in_patch, around ? &near_reach : nullptr,
                                  reach, threads, progress);
  if (!candidates) return {};
  const auto& faces = candidates->faces;
  const auto& scaled = candidates->scaled;
  const int patch_triangles = static_cast<int>(triangles.size());
  // The exact test takes the coordinates as stored.
  const auto corners_of = [&](int o) -> std::array<Point, 3> {
    if (o < patch_triangles) return triangles[o];
    auto fv = others.cfv_iter(faces[o]);
    return {others.point(*fv), others.point(*++fv), others.point(*++fv)};
  };
  const FaceGrid grid(std::move(candidates->boxes), threads);
  auto scan = [&](int begin, int end, std::vector<IntersectingPair>& pairs) {
    for (int i = begin; i < end; ++i) {
      if (stop_at(i, progress)) return;
      if (!scaled[i] && !exact_too) continue;
      for (const int o : grid.near(box_of_corners(triangles[i]))) {
        if (o < patch_triangles && o <= i)
          continue;  // pairs within the patch: once, from the first
        const bool found = scaled[i] && scaled[o] && triangles_intersect(*scaled[i], *scaled[o]);
        if (!found && !(exact_too && exactly_intersect_filtered(triangles[i], corners_of(o)))) {
          continue;
        }
        pairs.push_back(o < patch_triangles ? IntersectingPair{i, o, FaceHandle()}
                                            : IntersectingPair{i, -1, faces[o]});
      }
    }
  };
  // A large patch (a hole of a thousand edges refined) is scanned in blocks on the threads the
  // index allows, the blocks' pairs joined in order: the pairs of one thread.
  const int blocks = static_cast<int>(blocks_of(triangles.size(), kTrianglesPerBlock));
  if (threads < 2 || blocks < 2) {
    std::vector<IntersectingPair> pairs;
    scan(0, patch_triangles, pairs);
    return pairs;
  }
  std::vector<std::vector<IntersectingPair>> block_pairs(static_cast<std::size_t>(blocks));
  for_each_index(block_pairs.size(), threads, [&](std::size_t block) {
    const int begin = static_cast<int>(block) * kTrianglesPerBlock;
    scan(begin, std::min(patch_triangles, begin + kTrianglesPerBlock), block_pairs[block]);
  });
  std::vector<IntersectingPair> pairs;
  for (const auto& block : block_pairs) pairs.insert(pairs.end(), block.begin(), block.end());
  return pairs;
}

std::vector<std::pair<int, int>> chords_through_mesh(const Mesh& mesh,
                                                     const std::vector<Point>& points,
                                                     const MeshFaceIndex* around,
                                                     const std::vector<std::pair<int, int>>* among,
                                                     const Progress* progress) {
  const int n = static_cast<int>(points.size());
  Box reach;
  for (const auto& p : points) reach.add(p);
  std::optional<MeshFaceIndex> own;
  if (!around) around = &own.emplace(mesh, std::vector<Box>{reach});
  const Mesh& others = around->mesh();  // the patch's mesh, or the one it is filled apart from
  std::vector<int> faces = around->near(reach);
  double magnitude = reach.magnitude();
  std::vector<std::pair<int, Box>> boxes;
  for (const int f : faces) {
    boxes.emplace_back(static_cast<int>(boxes.size()), box_of(others, FaceHandle(f)));
    magnitude = std::max(magnitude, boxes.back().second.magnitude());
  }
  const double scale = scale_for(magnitude);
  std::vector<std::optional<Triangle3>> triangles;
  for (const int f : faces) {
    if (others.valence(FaceHandle(f)) != 3) {
      triangles.emplace_back();
      continue;
    }
    auto fv = others.cfv_iter(FaceHandle(f));
    triangles.push_back(
        triangle_from({others.point(*fv), others.point(*++fv), others.point(*++fv)}, scale));
  }
  const SegmentBoxTree tree(std::move(boxes));
  std::vector<std::pair<int, int>> chords;
  std::size_t tested = 0;
  auto test = [&](int i, int k) {
    if (k - i < 2 || (i == 0 && k == n - 1)) return;
    const bool through = tree.any_along(points[i], points[k], [&](int o) {
      return triangles[o] &&
             segment_enters_triangle(points[i] * scale, points[k] * scale, *triangles[o]);
    });
    if (through) chords.emplace_back(i, k);
  };
  if (among) {
    for (const auto& [i, k] : *among) {
      if (stop_at(++tested, progress)) break;
      test(i, k);
    }
    return chords;
  }
  for (int i = 0; i < n && !is_cancelled(progress); ++i) {
    for (int k = i + 2; k < n; ++k) test(i, k);
  }
  return chords;
}

std::vector<IntersectingPair> patch_intersections(const Mesh& mesh, const Patch& patch,
                                                  const MeshFaceIndex* around, bool exact_too,
                                                  const Progress* progress) {
  // A set over the patch's faces, not a flag per face of the mesh: this runs after every stage of
  // every hole, and on a 10M-face mesh clearing and faulting in those flags was most of a fill.
  const PatchFaceSet in_patch(patch);
  std::vector<std::array<Point, 3>> triangles(patch.faces.size());
  for_each_block(triangles.size(), kCandidatesPerBlock, around ? around->threads() : 1,
                 [&](std::size_t begin, std::size_t end, std::size_t) {
                   for (std::size_t t = begin; t < end; ++t) {
                     int c = 0;
                     for (const auto v : mesh.fv_range(patch.faces[t])) {
                       triangles[t][c++ % 3] = mesh.point(v);
                     }
                   }
                 });
  return triangle_intersections(mesh, triangles, &in_patch, around, exact_too, progress);
}

}  // namespace holefill::detail
