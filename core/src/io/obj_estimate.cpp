#include "obj_estimate.h"

#include <algorithm>
#include <cstring>

#include "text_scan.h"

namespace holefill::io {
namespace {

constexpr std::size_t kObjSamples = 64, kObjSampleBytes = std::size_t{8} << 10;

// Counts the statements of the whole lines in `lines` into `counts`.
void count_sampled_statements(std::string_view lines, ObjCounts& counts) {
  while (!lines.empty()) {
    const void* end = std::memchr(lines.data(), '\n', lines.size());
    const std::size_t length =
        end ? static_cast<std::size_t>(static_cast<const char*>(end) - lines.data()) : lines.size();
    std::string_view line = lines.substr(0, length);
    lines.remove_prefix(std::min(lines.size(), length + 1));
    const std::string_view keyword = take_token(line);
    if (keyword == "v") {
      ++counts.vertices;
    } else if (keyword == "vt") {
      ++counts.texcoords;
    } else if (keyword == "vn") {
      ++counts.normals;
    } else if (keyword == "f" || keyword == "fo") {
      ++counts.faces;
      for (std::string_view corner = take_token(line); !corner.empty(); corner = take_token(line)) {
        ++counts.corners;
        if (corner.find('/') != std::string_view::npos) counts.slashed_corners = true;
      }
    }
  }
}

// `sampled` out of `total` bytes held `count`: the total's estimate, an eighth more, at most
// `most`.
std::size_t estimate_from_sample(std::size_t count, std::size_t sampled, std::size_t total,
                                 std::size_t most) {
  if (count == 0) return 0;
  const double estimate = static_cast<double>(count) * static_cast<double>(total) /
                          static_cast<double>(sampled) * 1.125;
  return std::min(most, static_cast<std::size_t>(estimate) + 1);
}

}  // namespace

ObjCounts estimate_obj_counts(std::string_view text) {
  if (text.size() < kEstimateObjFrom) return {};
  ObjCounts sampled;
  std::size_t sampled_bytes = 0;
  for (std::size_t s = 0; s < kObjSamples; ++s) {
    // Whole lines from the first line start at or after the sample's place.
    std::size_t begin = text.size() / kObjSamples * s;
    if (begin > 0) {
      const void* end = std::memchr(text.data() + begin - 1, '\n', text.size() - begin + 1);
      if (!end) break;
      begin = static_cast<std::size_t>(static_cast<const char*>(end) - text.data()) + 1;
    }
    std::size_t stop = std::min(text.size(), begin + kObjSampleBytes);
    if (stop < text.size()) {
      const void* end = std::memchr(text.data() + stop, '\n', text.size() - stop);
      stop = end ? static_cast<std::size_t>(static_cast<const char*>(end) - text.data()) + 1
                 : text.size();
    }
    if (begin >= stop) continue;
    count_sampled_statements(text.substr(begin, stop - begin), sampled);
    sampled_bytes += stop - begin;
  }
  if (sampled_bytes == 0) return {};
  const std::size_t size = text.size();
  // The shortest statements: "v 0 0 0\n", "vt 0\n", "vn 0 0 0\n", "f 1\n" ("1 " a corner).
  ObjCounts counts;
  counts.vertices = estimate_from_sample(sampled.vertices, sampled_bytes, size, size / 8);
  counts.texcoords = estimate_from_sample(sampled.texcoords, sampled_bytes, size, size / 5);
  counts.normals = estimate_from_sample(sampled.normals, sampled_bytes, size, size / 9);
  counts.faces = estimate_from_sample(sampled.faces, sampled_bytes, size, size / 4);
  counts.corners = estimate_from_sample(sampled.corners, sampled_bytes, size, size / 2);
  counts.slashed_corners = sampled.slashed_corners;
  return counts;
}

}  // namespace holefill::io
