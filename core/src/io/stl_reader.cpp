#include <algorithm>
#include <charconv>
#include <cstring>
#include <string>

#include "readers.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

namespace {

class Welder {
 public:
  explicit Welder(Soup& soup) : soup_(soup) {}
  int vertex(const Point& p) {
    const auto [found, added] = index_.try_emplace(PositionKey(p), 0);
    if (added) {
      found->second = static_cast<int>(soup_.positions.size());
      soup_.positions.push_back(p);
    }
    return found->second;
  }

 private:
  Soup& soup_;
  std::unordered_map<PositionKey, int, PositionHash> index_;
};

constexpr std::size_t kStlHeader = 84, kStlRecord = 50;

}  // namespace

bool binary_stl_size_matches(std::string_view bytes, std::uint32_t& count) {
  return binary_stl_size_matches(bytes, bytes.size(), count);
}

bool binary_stl_size_matches(std::string_view first_bytes, std::uint64_t file_size,
                             std::uint32_t& count) {
  const std::string_view bytes = first_bytes;
  if (bytes.size() < kStlHeader) return false;
  unsigned char raw[4];
  std::memcpy(raw, bytes.data() + 80, 4);
  count = static_cast<std::uint32_t>(raw[0]) | static_cast<std::uint32_t>(raw[1]) << 8 |
          static_cast<std::uint32_t>(raw[2]) << 16 | static_cast<std::uint32_t>(raw[3]) << 24;
  return kStlHeader + kStlRecord * static_cast<std::uint64_t>(count) == file_size;
}

namespace {

float little_endian_float(const char* at) {
  unsigned char raw[4];
  std::memcpy(raw, at, 4);
  if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + 4);
  float value;
  std::memcpy(&value, raw, 4);
  return value;
}

Soup parse_binary_stl(std::string_view bytes, std::uint32_t count, const fs::path& path) {
  Soup soup;
  Welder welder(soup);
  soup.corners.reserve(3 * static_cast<std::size_t>(count));
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + kStlHeader + kStlRecord * static_cast<std::size_t>(t);
    for (int corner = 0; corner < 3; ++corner) {
      Point p;
      for (int axis = 0; axis < 3; ++axis) {
        p[axis] = little_endian_float(record + 12 + 12 * corner + 4 * axis);
      }
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
        throw InvalidMeshError(path, "triangle " + std::to_string(t + 1) +
                                         " has a non-finite (NaN or infinite) coordinate");
      }
      soup.corners.push_back(welder.vertex(p));
    }
    soup.end_face(soup.corners.size(), 0);
  }
  return soup;
}

Soup parse_ascii_stl(std::string_view text, const fs::path& path) {
  require_text(text, path, "ASCII STL");
  Soup soup;
  Welder welder(soup);
  Lines lines(text);
  std::string_view line;
  bool in_facet = false;
  while (lines.next(line)) {
    std::string_view rest = line;
    const std::string_view keyword = take_token(rest);
    if (keyword.empty() || keyword == "solid" || keyword == "endsolid" || keyword == "outer" ||
        keyword == "endloop") {
      continue;
    }
    if (keyword == "facet") {
      if (in_facet) fail(path, at_line(lines.number()) + "a facet inside a facet");
      in_facet = true;
    } else if (keyword == "vertex") {
      if (!in_facet) fail(path, at_line(lines.number()) + "a vertex outside a facet");
      Point p;
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view token = take_token(rest);
        if (!parse_double(token, p[axis])) {
          fail(path, at_line(lines.number()) + "vertex needs 3 numbers" +
                         (token.empty() ? std::string() : ", got " + quoted(token)));
        }
      }
      require_finite(p, soup.positions.size() + 1, lines.number(), path);
      soup.corners.push_back(welder.vertex(p));
    } else if (keyword == "endfacet") {
      if (!in_facet) fail(path, at_line(lines.number()) + "'endfacet' without 'facet'");
      in_facet = false;
      soup.end_face(soup.corners.size(), lines.number());
    } else {
      fail(path, at_line(lines.number()) + "unexpected " + quoted(keyword) + " in an ASCII STL");
    }
  }
  if (in_facet) fail(path, "ends inside a facet (truncated?)");
  return soup;
}

}  // namespace

// A file that is no ASCII STL is read as binary when its header's triangles fit in it; bytes
// after them (padding, an exporter's signature) are ignored with a warning, since the count says
// where the mesh ends.
Soup parse_stl(std::string_view bytes, const fs::path& path, LoadReport& report) {
  std::uint32_t count = 0;
  if (binary_stl_size_matches(bytes, count)) return parse_binary_stl(bytes, count, path);
  const bool ascii = starts_with_word(bytes, "solid") && bytes.find('\0') == std::string_view::npos;
  if (ascii) return parse_ascii_stl(bytes, path);
  if (bytes.size() < kStlHeader) {
    fail(path,
         "is no ASCII STL (it does not start with 'solid') and shorter than a binary STL's "
         "84-byte header (truncated or not an STL)");
  }
  const std::uint64_t needed = kStlHeader + kStlRecord * static_cast<std::uint64_t>(count);
  if (needed > bytes.size()) {
    fail(path,
         "is not an ASCII STL (it does not start with 'solid', or holds binary data), and "
         "as a binary STL it is truncated or corrupt: its header counts " +
             std::to_string(count) + " triangles, the file holds " +
             std::to_string((bytes.size() - kStlHeader) / kStlRecord));
  }
  report.warnings.push_back(std::to_string(bytes.size() - needed) + " bytes after the " +
                            std::to_string(count) +
                            " triangles the binary STL header counts were ignored");
  return parse_binary_stl(bytes, count, path);
}

}  // namespace holefill::io
