#include "ply_header.h"

#include <algorithm>
#include <unordered_set>

#include "soup.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;
namespace {

bool parse_ply_type(std::string_view name, PlyType& type) {
  static const std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [text, value] : kNames) {
    if (name == text) {
      type = value;
      return true;
    }
  }
  return false;
}

}  // namespace

std::size_t size_of(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 8;
}

namespace {

// A header that promises more records than the body can hold is corrupt, and must not make us
// allocate for them. The fewest bytes a value takes: 2 in ASCII ("0 "), its size in binary.
void require_room_for_counts(const PlyHeader& header, std::uint64_t body_size,
                             const fs::path& path) {
  auto smallest = [&header](PlyType type) {
    return header.encoding == PlyEncoding::Ascii ? std::size_t{2} : size_of(type);
  };
  unsigned long long least_bytes = 0;
  for (const auto& element : header.elements) {
    std::size_t record = 0;
    for (const auto& property : element.properties) {
      record += smallest(property.is_list ? property.count_type : property.type);
    }
    if (record == 0) {
      if (element.count == 0) continue;
      fail(path, "the header gives the '" + element.name + "' element " +
                     std::to_string(element.count) + " records but no properties (corrupt header)");
    }
    if (element.count > (body_size + 1) / record ||
        (least_bytes += element.count * record) > body_size + 1) {
      fail(path, "the header promises " + std::to_string(element.count) + " '" + element.name +
                     "' elements, more than the remaining " + std::to_string(body_size) +
                     " bytes of the file can hold (corrupt header or truncated file)");
    }
  }
}

void require_vertex_positions(const PlyHeader& header, const fs::path& path) {
  for (const auto& element : header.elements) {
    if (element.name != "vertex") continue;
    for (const char* axis : {"x", "y", "z"}) {
      if (std::none_of(element.properties.begin(), element.properties.end(),
                       [&](const PlyProperty& p) { return !p.is_list && p.name == axis; })) {
        fail(path, "the vertex element lacks an x, y or z property");
      }
    }
    if (element.count > static_cast<unsigned long long>(kMaxVertices)) {
      fail(path, "more vertices than holefill supports");
    }
    return;
  }
  fail(path, "has no 'vertex' element");
}

}  // namespace

PlyHeader parse_ply_header(std::string_view bytes, std::uint64_t file_size, const fs::path& path) {
  PlyHeader header;
  Lines lines(bytes);
  std::string_view line;
  std::string_view magic;
  if (lines.next(line)) {
    magic = line;
    skip_blanks(magic);
    while (!magic.empty() && is_blank(magic.back())) magic.remove_suffix(1);
  }
  if (magic != "ply") fail(path, "does not start with the line 'ply'");
  bool have_format = false, ended = false;
  // Names seen, so that a repeated one is found without a pass over the others (200,000
  // elements took 48 s that way).
  std::unordered_set<std::string> element_names, property_names;
  while (!ended && lines.next(line)) {
    const std::string where = at_line(lines.number());
    std::string_view rest = line;
    const std::string_view keyword = take_token(rest);
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      const std::string_view name = take_token(rest);
      if (name == "ascii") {
        header.encoding = PlyEncoding::Ascii;
      } else if (name == "binary_little_endian") {
        header.encoding = PlyEncoding::BinaryLittleEndian;
      } else if (name == "binary_big_endian") {
        header.encoding = PlyEncoding::BinaryBigEndian;
      } else {
        fail(path, where + "unknown PLY format " + quoted(name));
      }
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(take_token(rest));
      long long count = -1;
      const std::string_view count_text = take_token(rest);
      if (element.name.empty() || !parse_integer(count_text, count) || count < 0) {
        fail(path, where + "an element needs a name and a count, got " + quoted(line));
      }
      element.count = static_cast<unsigned long long>(count);
      if (!take_token(rest).empty()) {
        fail(path, where + "unexpected text after the element count in " + quoted(line));
      }
      if (!element_names.insert(element.name).second) {
        fail(path, where + "a second '" + element.name + "' element");
      }
      property_names.clear();
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail(path, where + "a property before any element");
      PlyProperty property;
      std::string_view type_name = take_token(rest);
      if (type_name == "list") {
        property.is_list = true;
        if (!parse_ply_type(take_token(rest), property.count_type) ||
            !is_integer_type(property.count_type)) {
          fail(path, where + "a list property needs an integer count type, got " + quoted(line));
        }
        type_name = take_token(rest);
      }
      if (!parse_ply_type(type_name, property.type)) {
        fail(path, where + "unknown property type " + quoted(type_name));
      }
      property.name = std::string(take_token(rest));
      if (property.name.empty()) fail(path, where + "a property needs a name");
      if (!take_token(rest).empty()) {
        fail(path, where + "unexpected text after the property name in " + quoted(line));
      }
      PlyElement& element = header.elements.back();
      if (element.properties.size() == kMaxPlyProperties) {
        fail(path, where + "the '" + element.name + "' element has more than " +
                       std::to_string(kMaxPlyProperties) +
                       " properties, the most holefill reads (kMaxPlyProperties in "
                       "core/src/io/ply_header.h)");
      }
      if (!property_names.insert(property.name).second) property.repeats_line = lines.number();
      element.properties.push_back(std::move(property));
    } else if (keyword == "end_header") {
      ended = true;
    } else {
      header.unknown_lines.push_back(lines.number());
    }
  }
  if (!ended) fail(path, "the header has no 'end_header' line (truncated?)");
  if (!have_format) fail(path, "the header has no 'format' line");
  header.body_offset = lines.offset();
  header.header_lines = lines.number();
  require_room_for_counts(header, file_size - header.body_offset, path);
  require_vertex_positions(header, path);
  return header;
}

}  // namespace holefill::io
