#include "holefill/fill_sequence.h"

#include <algorithm>

#include "advance_unscaled.h"
#include "face_grid.h"
#include "mesh_face_index.h"
#include "safe_scale.h"

namespace holefill {

FillSequence::FillSequence(Mesh& mesh, const std::vector<std::vector<const Hole*>>& groups)
    : mesh_(mesh), groups_(groups), largest_(detail::SafeScale::largest_coordinate(mesh)) {}

FillSequence::~FillSequence() = default;

StageRun FillSequence::step(const std::vector<const Hole*>& loops, HoleFill& fill,
                            const FillOptions& options) {
  // Original vertices never move nor go, and new ones only add to largest_: the mesh's largest
  // coordinate lies between the first measure and largest_, so SafeScale would leave the mesh as
  // it is when it would leave both. Otherwise advance_joined() measures and scales it.
  if (!detail::SafeScale::leaves_alone(largest_)) {
    return advance_joined(mesh_, loops, fill, options);
  }
  const int hole = loops.empty() ? -1 : loops.front()->id;
  if (hole != current_hole_) {
    const bool fresh = fill.stage() == Stage::Original && !fill.failed() &&
                       std::find(left_holes_.begin(), left_holes_.end(), hole) == left_holes_.end();
    leave_current_hole();
    current_hole_ = hole;
    // The index holds the faces as they were when it was made, and each patch finished since:
    // a patch begun before, or changed after it joined, would be missing or out of date.
    if (!fresh) index_given_up_ = true;
  }
  if (index_given_up_) index_.reset();
  if (!index_ && !index_given_up_) {
    std::vector<detail::Box> regions;
    for (const auto& group : groups_) {
      std::vector<VertexHandle> vertices;
      for (const Hole* loop : group) {
        vertices.insert(vertices.end(), loop->vertices.begin(), loop->vertices.end());
      }
      regions.push_back(detail::neighbourhood_of(mesh_, vertices));
    }
    const Progress* progress = options.triangulate.progress;
    index_ = std::make_unique<detail::MeshFaceIndex>(mesh_, regions, 1, progress);
    // Cancelled while filing, the index is incomplete: the step below fails as cancelled at its
    // first look without it, and a later step files again.
    if (is_cancelled(progress)) index_.reset();
  }
  current_fill_ = &fill;
  const StageRun run = detail::advance_unscaled(mesh_, loops, fill, options, index_.get());
  for (const auto v : fill.patch.new_vertices) {
    largest_ = std::max(largest_, detail::SafeScale::largest_coordinate(mesh_.point(v)));
  }
  return run;
}

void FillSequence::leave_current_hole() {
  if (current_hole_ < 0) return;
  left_holes_.push_back(current_hole_);
  if (index_ && current_fill_) {
    for (const auto f : current_fill_->patch.faces) index_->add(f.idx(), detail::box_of(mesh_, f));
  }
  current_fill_ = nullptr;
}

}  // namespace holefill
