// The header of a PLY file: its encoding, elements and their typed properties, and where the
// body starts. Checked against the size of the whole file, so that a corrupt or absurd header is
// refused before any of the body is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "holefill/attributes.h"

namespace holefill::io {

using PlyType = ScalarType;

// Bytes one value of `type` takes in a binary body.
std::size_t size_of(PlyType type);
// Inline, as fits: both are asked for every value of an ASCII body.
inline bool is_integer_type(PlyType type) {
  return type != PlyType::Float32 && type != PlyType::Float64;
}
// `value` lies in the range of the integer type `type`.
inline bool fits(long long value, PlyType type) {
  switch (type) {
    case PlyType::Int8:
      return value >= -128 && value <= 127;
    case PlyType::UInt8:
      return value >= 0 && value <= 255;
    case PlyType::Int16:
      return value >= -32768 && value <= 32767;
    case PlyType::UInt16:
      return value >= 0 && value <= 65535;
    case PlyType::Int32:
      return value >= -2147483648LL && value <= 2147483647LL;
    case PlyType::UInt32:
      return value >= 0 && value <= 4294967295LL;
    case PlyType::Float32:
    case PlyType::Float64:
      break;
  }
  return true;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the items, for a list
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  // An earlier property of the element has this name: its values are read past, not kept (the
  // mesh holds one attribute per name), and the reader says so.
  std::size_t repeats_line = 0;  // the header line that repeats the name, or 0
};

// The most properties one element may declare: values are kept per property (an OpenMesh
// property each, whose container searches its properties one by one as each is added), so that
// work grows with the square of their number; 100,000 took minutes. A file with more is refused
// with this limit named.
inline constexpr std::size_t kMaxPlyProperties = 10000;

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
};

using PlyEncoding = FileEncoding;

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;   // bytes before the body
  std::size_t header_lines = 0;  // lines before the body, for messages about ASCII body lines
  // Header lines with no PLY keyword (old exporters wrote bare text as a comment): skipped.
  std::vector<std::size_t> unknown_lines;
};

// The header at the start of `bytes` (which may be only the file's first bytes) of a PLY file of
// `file_size` bytes. Throws FileError naming the line and reason for a malformed header, a vertex
// element without x, y and z, two elements of one name, an element with more than
// kMaxPlyProperties properties, or counts that more bytes than the file has would be needed for.
// Linear in the header's length.
PlyHeader parse_ply_header(std::string_view bytes, std::uint64_t file_size,
                           const std::filesystem::path& path);

}  // namespace holefill::io
