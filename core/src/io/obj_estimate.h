// How many elements an OBJ text holds, estimated from samples of it, so that the reader can give
// its arrays their room at the start: grown by doubling, a 1M-face textured OBJ's arrays were
// copied and faulted in about twice over (a fifth of reading it). An estimate only: a reader
// whose arrays outgrow it grows them as before, so the soup is the same either way.
#pragma once

#include <cstddef>
#include <string_view>

namespace holefill::io {

struct ObjCounts {
  std::size_t vertices = 0, texcoords = 0, normals = 0, faces = 0, corners = 0;
  bool slashed_corners = false;  // some sampled corner has a texture coordinate or normal
};

// From a text of this size on, estimate_obj_counts samples it (a smaller text's arrays are
// small, and their doubling cheap).
inline constexpr std::size_t kEstimateObjFrom = std::size_t{1} << 20;

// The counts of `text`'s v, vt, vn and f statements and of the faces' corners, estimated from
// 64 evenly spaced runs of whole lines, 8 KB each, scaled to the text's size with an eighth more
// (a little more than the lines sampled say, where vertices and faces come in blocks); all
// zero below kEstimateObjFrom bytes. At most the size over the shortest statement of each kind.
ObjCounts estimate_obj_counts(std::string_view text);

}  // namespace holefill::io
