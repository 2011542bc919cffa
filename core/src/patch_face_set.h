// Which faces belong to one patch, asked for every edge the refinement and the remeshing look at.
// A patch's faces are among the newest of the mesh (faces are only appended while holes are
// filled), so one flag per face from the patch's oldest face on answers in one load, where a hash
// set took a tenth of the refinement's time; the flags cover only the faces added since.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "holefill/patch.h"

namespace holefill::detail {

class PatchFaceSet {
 public:
  explicit PatchFaceSet(const Patch& patch) {
    for (const auto f : patch.faces) first_ = std::min(first_, f.idx());
    for (const auto f : patch.faces) insert(f);
  }

  // Whether `face` (valid or not) is one of the set's.
  bool contains(FaceHandle face) const {
    const auto slot = static_cast<std::size_t>(face.idx()) - static_cast<std::size_t>(first_);
    return face.is_valid() && face.idx() >= first_ && slot < member_.size() && member_[slot];
  }

  // Adds `face` (a valid face); false when it was in already.
  bool insert(FaceHandle face) {
    if (face.idx() < first_) {  // older than every face so far (never while refining)
      const auto older = member_.empty() ? 0 : static_cast<std::size_t>(first_ - face.idx());
      member_.insert(member_.begin(), older, 0);
      first_ = face.idx();
    }
    const auto slot = static_cast<std::size_t>(face.idx() - first_);
    if (slot >= member_.size()) member_.resize(slot + 1, 0);
    if (member_[slot]) return false;
    member_[slot] = 1;
    return true;
  }

 private:
  int first_ = std::numeric_limits<int>::max();
  std::vector<std::uint8_t> member_;  // member_[i]: face first_ + i is in the set
};

}  // namespace holefill::detail
