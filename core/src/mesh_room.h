// The room a mesh's arrays are given beyond their elements: an eighth more (what filling adds),
// so that adding the first patch does not copy an array into one twice its size beside the old
// one (on a big mesh, the peak of filling it).
#pragma once

#include <cstddef>

namespace holefill::detail {

inline std::size_t with_room(std::size_t count) { return count + count / 8 + 64; }

}  // namespace holefill::detail
