#include <algorithm>
#include <charconv>
#include <cstring>
#include <string>

#include "readers.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

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

bool is_integer_type(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the items, for a list
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { Ascii, LittleEndian, BigEndian };

// Reads the values of a PLY body, ASCII or binary, refusing to read past its end.
class PlyBody {
 public:
  PlyBody(std::string_view bytes, PlyEncoding encoding, const fs::path& path)
      : bytes_(bytes), encoding_(encoding), path_(path) {}

  // Where the reader is, for messages: set by the caller before each element record.
  void locate(const std::string& where) { where_ = where; }
  const std::string& where() const { return where_; }

  double read(PlyType type) {
    if (encoding_ == PlyEncoding::Ascii) return read_text(type);
    const std::size_t size = size_of(type);
    if (bytes_.size() - position_ < size) {
      fail(path_, "ends in the middle of " + where_ + " (truncated?)");
    }
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, size);
    position_ += size;
    const bool swap =
        (encoding_ == PlyEncoding::BigEndian) != (std::endian::native == std::endian::big);
    if (swap) std::reverse(raw, raw + size);
    switch (type) {
      case PlyType::Int8:
        return static_cast<double>(load<std::int8_t>(raw));
      case PlyType::UInt8:
        return static_cast<double>(load<std::uint8_t>(raw));
      case PlyType::Int16:
        return static_cast<double>(load<std::int16_t>(raw));
      case PlyType::UInt16:
        return static_cast<double>(load<std::uint16_t>(raw));
      case PlyType::Int32:
        return static_cast<double>(load<std::int32_t>(raw));
      case PlyType::UInt32:
        return static_cast<double>(load<std::uint32_t>(raw));
      case PlyType::Float32:
        return static_cast<double>(load<float>(raw));
      case PlyType::Float64:
        return load<double>(raw);
    }
    return 0.0;
  }

  // Bytes left; for ASCII, an upper bound on the values left.
  std::size_t remaining() const { return bytes_.size() - position_; }
  // The fewest bytes one value of `type` can take.
  std::size_t smallest(PlyType type) const {
    return encoding_ == PlyEncoding::Ascii ? 2 : size_of(type);
  }

 private:
  template <class T>
  static T load(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof value);
    return value;
  }

  double read_text(PlyType type) {
    while (position_ < bytes_.size() &&
           (is_blank(bytes_[position_]) || bytes_[position_] == '\n')) {
      ++position_;
    }
    std::size_t end = position_;
    while (end < bytes_.size() && !is_blank(bytes_[end]) && bytes_[end] != '\n') ++end;
    const std::string_view token = bytes_.substr(position_, end - position_);
    position_ = end;
    if (token.empty()) fail(path_, "ends in the middle of " + where_ + " (truncated?)");
    if (is_integer_type(type)) {
      long long value = 0;
      if (!parse_integer(token, value)) {
        fail(path_, where_ + ": expected a whole number, got " + quoted(token));
      }
      return static_cast<double>(value);
    }
    double value = 0.0;
    if (!parse_double(token, value)) {
      fail(path_, where_ + ": expected a number, got " + quoted(token));
    }
    return value;
  }

  std::string_view bytes_;
  PlyEncoding encoding_;
  const fs::path& path_;
  std::size_t position_ = 0;
  std::string where_;
};

}  // namespace

Soup parse_ply(std::string_view bytes, const fs::path& path) {
  Lines lines(bytes);
  std::string_view line;
  std::string_view magic;
  if (lines.next(line)) {
    magic = line;
    skip_blanks(magic);
    while (!magic.empty() && is_blank(magic.back())) magic.remove_suffix(1);
  }
  if (magic != "ply") fail(path, "does not start with the line 'ply'");
  std::vector<PlyElement> elements;
  PlyEncoding encoding = PlyEncoding::Ascii;
  bool have_format = false, ended = false;
  while (!ended && lines.next(line)) {
    const std::string where = at_line(lines.number());
    std::string_view rest = line;
    const std::string_view keyword = take_token(rest);
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      const std::string_view name = take_token(rest);
      if (name == "ascii") {
        encoding = PlyEncoding::Ascii;
      } else if (name == "binary_little_endian") {
        encoding = PlyEncoding::LittleEndian;
      } else if (name == "binary_big_endian") {
        encoding = PlyEncoding::BigEndian;
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
      elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (elements.empty()) fail(path, where + "a property before any element");
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
      elements.back().properties.push_back(std::move(property));
    } else if (keyword == "end_header") {
      ended = true;
    } else {
      fail(path, where + "unknown header line " + quoted(line));
    }
  }
  if (!ended) fail(path, "the header has no 'end_header' line (truncated?)");
  if (!have_format) fail(path, "the header has no 'format' line");
  const std::string_view body_bytes = bytes.substr(lines.offset());
  if (encoding == PlyEncoding::Ascii) require_text(body_bytes, path, "ASCII PLY");
  PlyBody body(body_bytes, encoding, path);

  // A header that promises more records than the body can hold is corrupt, and must not make us
  // allocate for them.
  unsigned long long least_bytes = 0;
  for (const auto& element : elements) {
    std::size_t record = 0;
    for (const auto& property : element.properties) {
      record += body.smallest(property.is_list ? property.count_type : property.type);
    }
    if (record == 0) {
      if (element.count == 0) continue;
      fail(path, "the header gives the '" + element.name + "' element " +
                     std::to_string(element.count) + " records but no properties (corrupt header)");
    }
    if (element.count > (body.remaining() + 1) / record ||
        (least_bytes += element.count * record) > body.remaining() + 1) {
      fail(path, "the header promises " + std::to_string(element.count) + " '" + element.name +
                     "' elements, more than the remaining " + std::to_string(body.remaining()) +
                     " bytes of the file can hold (corrupt header or truncated file)");
    }
  }

  Soup soup;
  const PlyElement* vertex_element = nullptr;
  std::vector<long long> corners;
  for (const auto& element : elements) {
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    int axis_of[3] = {-1, -1, -1};  // property index of x, y, z
    int face_list = -1;
    for (int i = 0; i < static_cast<int>(element.properties.size()); ++i) {
      const auto& property = element.properties[i];
      if (is_vertex && !property.is_list) {
        for (int axis = 0; axis < 3; ++axis) {
          if (property.name == std::string(1, static_cast<char>('x' + axis))) axis_of[axis] = i;
        }
      }
      if (is_face && property.is_list &&
          (face_list < 0 || property.name == "vertex_indices" || property.name == "vertex_index")) {
        face_list = i;
      }
    }
    if (is_vertex) {
      if (axis_of[0] < 0 || axis_of[1] < 0 || axis_of[2] < 0) {
        fail(path, "the vertex element lacks an x, y or z property");
      }
      if (element.count > static_cast<unsigned long long>(kMaxVertices)) {
        fail(path, "more vertices than holefill supports");
      }
      vertex_element = &element;
      soup.positions.reserve(element.count);
    }
    for (unsigned long long r = 0; r < element.count; ++r) {
      body.locate("'" + element.name + "' element " + std::to_string(r) + " of " +
                  std::to_string(element.count));
      Point p(0.0, 0.0, 0.0);
      for (int i = 0; i < static_cast<int>(element.properties.size()); ++i) {
        const auto& property = element.properties[i];
        if (!property.is_list) {
          const double value = body.read(property.type);
          for (int axis = 0; axis < 3; ++axis) {
            if (is_vertex && axis_of[axis] == i) p[axis] = value;
          }
          continue;
        }
        const double count = body.read(property.count_type);
        if (count < 0.0 ||
            count > static_cast<double>(body.remaining() / body.smallest(property.type) + 1)) {
          fail(path, body.where() + ": a list claims " +
                         std::to_string(static_cast<long long>(count)) +
                         " items, more than the rest of the file holds (truncated or corrupt)");
        }
        for (long long item = 0; item < static_cast<long long>(count); ++item) {
          const double value = body.read(property.type);
          if (i != face_list) continue;
          if (value < 0.0 || value != std::floor(value) || value > kMaxVertices) {
            fail(path, "face " + std::to_string(r) + " has an invalid vertex index " +
                           std::to_string(value));
          }
          corners.push_back(static_cast<long long>(value));
        }
      }
      if (is_vertex) {
        require_finite(p, r, 0, path);
        soup.positions.push_back(p);
      }
      if (is_face) soup.end_face(corners.size(), 0);
    }
  }
  if (!vertex_element) fail(path, "has no 'vertex' element");
  const long long vertex_count = static_cast<long long>(soup.positions.size());
  soup.corners.reserve(corners.size());
  for (std::size_t f = 0, c = 0; f < soup.face_count(); ++f) {
    for (; c < soup.face_end[f]; ++c) {
      if (corners[c] >= vertex_count) {
        fail(path, "face " + std::to_string(f) + " refers to vertex " + std::to_string(corners[c]) +
                       ", but the file has " + std::to_string(vertex_count) +
                       " vertices (numbered from 0)");
      }
      soup.corners.push_back(static_cast<int>(corners[c]));
    }
  }
  return soup;
}

}  // namespace holefill::io
