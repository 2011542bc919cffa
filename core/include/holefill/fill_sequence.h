// Many stages of many holes on one mesh, one step at a time (a viewer filling every hole, or
// replaying a log of steps): advance_joined() alone looks at the whole mesh at every step (for
// its scale and for the self-intersection checks), which made a thousand holes of a 2M-face scan
// take minutes. A FillSequence looks once, and checks each patch against an index of the faces
// near the holes, as fill_holes() does.
#pragma once

#include <memory>
#include <vector>

#include "holefill/fill.h"

namespace holefill {

namespace detail {
class MeshFaceIndex;
}

class FillSequence {
 public:
  // `mesh` must outlive the sequence and change only through step() while it lasts. `groups`:
  // the loops the steps will fill, each group filled together (as step() is given them); their
  // neighbourhoods are indexed at once, and the index files the faces near any other place when
  // a check looks there.
  FillSequence(Mesh& mesh, const std::vector<std::vector<const Hole*>>& groups);
  ~FillSequence();
  FillSequence(const FillSequence&) = delete;
  FillSequence& operator=(const FillSequence&) = delete;

  // advance_joined(mesh, loops, fill, options), with the same result. The index serves the steps
  // while they go hole by hole, each hole from its first stage; a step that returns to a hole
  // left before, or starts from a hole begun before the sequence, makes this and later steps
  // scan the mesh as advance_joined() does. A mesh whose scale the stages cannot take as it is
  // (a largest coordinate above 2^200 or below 2^-200, near where squared lengths overflow or
  // underflow) is scaled by a power of two at every step, as advance_joined() does.
  StageRun step(const std::vector<const Hole*>& loops, HoleFill& fill, const FillOptions& options);

 private:
  void leave_current_hole();

  Mesh& mesh_;
  std::vector<std::vector<const Hole*>> groups_;
  double largest_ = 0.0;  // at least the mesh's largest coordinate (SafeScale's measure)
  std::unique_ptr<detail::MeshFaceIndex> index_;  // null: steps scan the mesh
  bool index_given_up_ = false;
  int current_hole_ = -1;                   // the hole the last step was about
  const HoleFill* current_fill_ = nullptr;  // its fill, whose patch joins the index when left
  std::vector<int> left_holes_;             // holes stepped before the current one
};

}  // namespace holefill
