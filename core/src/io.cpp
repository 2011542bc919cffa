#include "holefill/io.h"

#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "holefill/errors.h"
#include "holefill/triangulate.h"

namespace holefill {
namespace fs = std::filesystem;

namespace {

enum class Format { Obj, Off, Ply, Stl, Unknown };

const char* name_of(Format format) {
  switch (format) {
    case Format::Obj:
      return "obj";
    case Format::Off:
      return "off";
    case Format::Ply:
      return "ply";
    case Format::Stl:
      return "stl";
    case Format::Unknown:
      break;
  }
  return "unknown";
}

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

Format format_of_extension(const std::string& ext) {
  if (ext == ".obj") return Format::Obj;
  if (ext == ".off") return Format::Off;
  if (ext == ".ply") return Format::Ply;
  if (ext == ".stl") return Format::Stl;
  return Format::Unknown;
}

[[noreturn]] void fail(const fs::path& path, const std::string& reason) {
  throw FileError(path, reason);
}

std::string at_line(std::size_t line) { return "line " + std::to_string(line) + ": "; }

// A short, printable excerpt of file text for a message (files may hold any bytes).
std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxShown = 24;
  std::string shown = "'";
  for (std::size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    shown += (c >= 0x20 && c < 0x7F) ? static_cast<char>(c) : '?';
  }
  if (text.size() > kMaxShown) shown += "...";
  return shown + "'";
}

// ---- Text scanning ----------------------------------------------------------------------------

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

void skip_blanks(std::string_view& text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
}

std::string_view take_token(std::string_view& text) {
  skip_blanks(text);
  std::size_t length = 0;
  while (length < text.size() && !is_blank(text[length])) ++length;
  const std::string_view token = text.substr(0, length);
  text.remove_prefix(length);
  return token;
}

// The whole token is a number (from_chars: locale-independent and correctly rounded).
bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;
  }
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (stop != end) return false;
  if (error == std::errc::result_out_of_range) {
    // Overflow reads as infinity (refused later as non-finite), underflow as a tiny number.
    value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return error == std::errc();
}

bool parse_integer(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token.front() == '-') return false;
  }
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  return stop == end && error == std::errc();
}

// Lines of a text, without their end-of-line characters, counted from 1.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (position_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', position_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(position_, end - position_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    position_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }
  // Bytes after the current line.
  std::size_t remaining() const { return position_ >= text_.size() ? 0 : text_.size() - position_; }
  std::size_t offset() const { return std::min(position_, text_.size()); }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  std::size_t number_ = 0;
};

// Text formats must not hold NUL bytes: a binary file with a text format's extension.
void require_text(std::string_view text, const fs::path& path, const char* format) {
  const std::size_t nul = text.find('\0');
  if (nul != std::string_view::npos) {
    fail(path, std::string("is not a text ") + format + " file: it holds binary data (byte " +
                   std::to_string(nul) + " is NUL)");
  }
}

// ---- The polygons a file describes --------------------------------------------------------------

// Positions and faces as read, before any check of the mesh they make.
struct Soup {
  std::vector<Point> positions;
  std::vector<int> corners;            // vertex indices of all faces, one after another
  std::vector<std::size_t> face_end;   // face f uses corners [face_end[f-1], face_end[f])
  std::vector<std::size_t> face_line;  // where face f was read (0: unknown), for messages
  std::size_t face_begin(std::size_t f) const { return f == 0 ? 0 : face_end[f - 1]; }
  std::size_t face_count() const { return face_end.size(); }
  // Closes the face whose last corner is corners[end - 1] (corners may be filled later).
  void end_face(std::size_t end, std::size_t line) {
    face_end.push_back(end);
    face_line.push_back(line);
  }
};

// Indices into the soup's positions are ints (as OpenMesh's handles are).
constexpr long long kMaxVertices = std::numeric_limits<int>::max() - 1;

void require_finite(const Point& p, std::size_t vertex_number, std::size_t line,
                    const fs::path& path) {
  if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) return;
  throw InvalidMeshError(path, (line ? at_line(line) : std::string()) + "vertex " +
                                   std::to_string(vertex_number) +
                                   " has a non-finite (NaN or infinite) coordinate");
}

// ---- OBJ
// ------------------------------------------------------------------------------------------

Soup parse_obj(std::string_view text, const fs::path& path, LoadReport& report) {
  require_text(text, path, "OBJ");
  Soup soup;
  std::vector<long long> corners;  // 0-based, checked against the vertex count at the end
  Lines lines(text);
  std::string_view line;
  std::string joined;
  while (lines.next(line)) {
    const std::size_t line_number = lines.number();
    // A backslash at the end of a line continues it on the next.
    if (!line.empty() && line.back() == '\\') {
      joined.assign(line.substr(0, line.size() - 1));
      std::string_view more;
      bool continued = true;
      while (continued && lines.next(more)) {
        continued = !more.empty() && more.back() == '\\';
        joined += ' ';
        joined += more.substr(0, more.size() - (continued ? 1 : 0));
      }
      line = joined;
    }
    std::string_view rest = line.substr(0, line.find('#'));  // comments run to the line's end
    const std::string_view keyword = take_token(rest);
    if (keyword.empty()) continue;
    if (keyword == "v") {
      Point p;
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view token = take_token(rest);
        if (!parse_double(token, p[axis])) {
          fail(path, at_line(line_number) + "vertex needs 3 numbers" +
                         (token.empty() ? std::string() : ", got " + quoted(token)));
        }
      }
      if (static_cast<long long>(soup.positions.size()) >= kMaxVertices) {
        fail(path, at_line(line_number) + "more vertices than holefill supports");
      }
      require_finite(p, soup.positions.size() + 1, line_number, path);
      soup.positions.push_back(p);
    } else if (keyword == "f" || keyword == "fo") {
      const std::size_t first = corners.size();
      for (std::string_view corner = take_token(rest); !corner.empty(); corner = take_token(rest)) {
        // "v", "v/vt", "v//vn" or "v/vt/vn": only the position index matters here.
        const std::string_view index_text = corner.substr(0, corner.find('/'));
        long long index = 0;
        if (!parse_integer(index_text, index)) {
          fail(path,
               at_line(line_number) + "face corner " + quoted(corner) + " is not a vertex index");
        }
        if (index == 0) fail(path, at_line(line_number) + "vertex index 0 (OBJ counts from 1)");
        const long long defined = static_cast<long long>(soup.positions.size());
        if (index < 0) {
          // Relative: -1 is the last vertex defined so far.
          if (index < -defined) {
            fail(path, at_line(line_number) + "relative vertex index " + std::to_string(index) +
                           " reaches before the first vertex");
          }
          index += defined;
        } else {
          index -= 1;
        }
        corners.push_back(index);
      }
      if (corners.size() == first) {
        ++report.degenerate_faces_dropped;
        continue;
      }
      soup.end_face(corners.size(), line_number);
    } else if (keyword == "l" || keyword == "p" || keyword == "curv" || keyword == "curv2" ||
               keyword == "surf") {
      ++report.elements_ignored;
    }
  }
  const long long vertex_count = static_cast<long long>(soup.positions.size());
  soup.corners.reserve(corners.size());
  for (std::size_t f = 0, c = 0; f < soup.face_count(); ++f) {
    for (; c < soup.face_end[f]; ++c) {
      if (corners[c] >= vertex_count) {
        fail(path, at_line(soup.face_line[f]) + "face refers to vertex " +
                       std::to_string(corners[c] + 1) + ", but the file has " +
                       std::to_string(vertex_count) + " vertices");
      }
      soup.corners.push_back(static_cast<int>(corners[c]));
    }
  }
  return soup;
}

// ---- OFF
// ------------------------------------------------------------------------------------------

// "OFF" with the optional prefixes of the format: ST (texture), C (colour), N (normal), 4 (4D),
// n (nD). Returns false when `keyword` is no OFF keyword.
bool parse_off_keyword(std::string_view keyword, bool& three_dimensional) {
  constexpr std::string_view kOff = "OFF";
  if (keyword.size() < kOff.size() || keyword.substr(keyword.size() - kOff.size()) != kOff) {
    return false;
  }
  std::string_view prefix = keyword.substr(0, keyword.size() - kOff.size());
  if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
  for (const char letter : {'C', 'N', '4', 'n'}) {
    if (!prefix.empty() && prefix.front() == letter) prefix.remove_prefix(1);
  }
  three_dimensional = keyword.find_first_of("4n") == std::string_view::npos;
  return prefix.empty();
}

Soup parse_off(std::string_view text, const fs::path& path) {
  require_text(text, path, "OFF");
  Lines lines(text);
  // The next line with content, comments ('#' to the end of the line) removed.
  auto next_content = [&lines](std::string_view& line) {
    while (lines.next(line)) {
      line = line.substr(0, line.find('#'));
      skip_blanks(line);
      if (!line.empty()) return true;
    }
    return false;
  };
  std::string_view line;
  if (!next_content(line)) fail(path, "holds no OFF header, only blank or comment lines");
  std::string_view rest = line;
  const std::string_view keyword = take_token(rest);
  bool three_dimensional = true;
  if (!parse_off_keyword(keyword, three_dimensional)) {
    fail(path, "does not start with an OFF header (found " + quoted(keyword) + ")");
  }
  if (!three_dimensional) {
    fail(path, "only 3D OFF files are supported (header " + quoted(keyword) + ")");
  }
  skip_blanks(rest);
  if (rest.substr(0, 6) == "BINARY") {
    fail(path, "binary OFF is not supported; save it as ASCII OFF, PLY or OBJ");
  }
  if (rest.empty() && !next_content(rest)) fail(path, "ends after its header keyword");
  const std::size_t counts_line = lines.number();
  long long counts[2] = {0, 0};
  for (auto& count : counts) {
    const std::string_view token = take_token(rest);
    if (!parse_integer(token, count) || count < 0) {
      fail(path, at_line(counts_line) + "the header needs vertex and face counts" +
                     (token.empty() ? std::string() : ", got " + quoted(token)));
    }
  }
  const auto vertex_count = static_cast<unsigned long long>(counts[0]);
  const auto face_count = static_cast<unsigned long long>(counts[1]);
  // A vertex takes at least 6 bytes ("0 0 0\n"), a face at least 2 ("0\n"): a header that
  // promises more than the file can hold is corrupt, and must not make us allocate for it.
  const unsigned long long room = lines.remaining() + 1;
  if (vertex_count > room / 6 || face_count > room / 2 ||
      vertex_count * 6 + face_count * 2 > room + 1) {
    fail(path, at_line(counts_line) + "the header promises " + std::to_string(vertex_count) +
                   " vertices and " + std::to_string(face_count) +
                   " faces, more than the remaining " + std::to_string(lines.remaining()) +
                   " bytes of the file can hold (corrupt header or truncated file)");
  }
  Soup soup;
  soup.positions.reserve(vertex_count);
  for (unsigned long long v = 0; v < vertex_count; ++v) {
    if (!next_content(line)) {
      fail(path, "ends after " + std::to_string(v) + " of its " + std::to_string(vertex_count) +
                     " vertices (truncated?)");
    }
    Point p;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view token = take_token(line);
      if (!parse_double(token, p[axis])) {
        fail(path, at_line(lines.number()) + "vertex needs 3 numbers" +
                       (token.empty() ? std::string() : ", got " + quoted(token)));
      }
    }
    require_finite(p, v, lines.number(), path);
    soup.positions.push_back(p);
  }
  for (unsigned long long f = 0; f < face_count; ++f) {
    if (!next_content(line)) {
      fail(path, "ends after " + std::to_string(f) + " of its " + std::to_string(face_count) +
                     " faces (truncated?)");
    }
    long long corner_count = 0;
    const std::string_view count_token = take_token(line);
    if (!parse_integer(count_token, corner_count) || corner_count < 0) {
      fail(path, at_line(lines.number()) + "a face must start with its number of corners, got " +
                     quoted(count_token));
    }
    for (long long c = 0; c < corner_count; ++c) {
      const std::string_view token = take_token(line);
      long long index = 0;
      if (!parse_integer(token, index)) {
        fail(path, at_line(lines.number()) + "face needs " + std::to_string(corner_count) +
                       " vertex indices" +
                       (token.empty() ? std::string() : ", got " + quoted(token)));
      }
      if (index < 0 || static_cast<unsigned long long>(index) >= vertex_count) {
        fail(path, at_line(lines.number()) + "face refers to vertex " + std::to_string(index) +
                       ", but the file has " + std::to_string(vertex_count) +
                       " vertices (numbered from 0)");
      }
      soup.corners.push_back(static_cast<int>(index));
    }
    soup.end_face(soup.corners.size(), lines.number());
  }
  return soup;
}

// ---- PLY
// ------------------------------------------------------------------------------------------

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

// ---- STL
// ------------------------------------------------------------------------------------------

// Exact positions as hash keys (-0 and +0 are one position).
struct PositionKey {
  std::array<std::uint64_t, 3> bits;
  explicit PositionKey(const Point& p) {
    for (int axis = 0; axis < 3; ++axis) bits[axis] = std::bit_cast<std::uint64_t>(p[axis] + 0.0);
  }
  bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
  std::size_t operator()(const PositionKey& key) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const auto b : key.bits) h = (h ^ b) * 0x100000001B3ull + (h >> 29);
    return static_cast<std::size_t>(h);
  }
};

// STL stores each triangle's corners by value: equal positions are welded into one vertex.
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

// The triangle count in a binary STL header, and whether the file's size agrees with it.
bool binary_stl_size_matches(std::string_view bytes, std::uint32_t& count) {
  if (bytes.size() < kStlHeader) return false;
  unsigned char raw[4];
  std::memcpy(raw, bytes.data() + 80, 4);
  count = static_cast<std::uint32_t>(raw[0]) | static_cast<std::uint32_t>(raw[1]) << 8 |
          static_cast<std::uint32_t>(raw[2]) << 16 | static_cast<std::uint32_t>(raw[3]) << 24;
  return kStlHeader + kStlRecord * static_cast<std::uint64_t>(count) == bytes.size();
}

float little_endian_float(const char* at) {
  unsigned char raw[4];
  std::memcpy(raw, at, 4);
  if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + 4);
  float value;
  std::memcpy(&value, raw, 4);
  return value;
}

bool starts_with_word(std::string_view text, std::string_view word) {
  while (!text.empty() && (is_blank(text.front()) || text.front() == '\n')) text.remove_prefix(1);
  return text.substr(0, word.size()) == word &&
         (text.size() == word.size() || is_blank(text[word.size()]) || text[word.size()] == '\n');
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

Soup parse_stl(std::string_view bytes, const fs::path& path) {
  std::uint32_t count = 0;
  if (binary_stl_size_matches(bytes, count)) return parse_binary_stl(bytes, count, path);
  const std::string binary_size =
      bytes.size() < kStlHeader
          ? "it is shorter than a binary STL's 84-byte header"
          : "a binary STL with the " + std::to_string(count) +
                " triangles its header counts takes " +
                std::to_string(kStlHeader + kStlRecord * static_cast<std::uint64_t>(count)) +
                " bytes, but the file has " + std::to_string(bytes.size());
  if (!starts_with_word(bytes, "solid")) {
    fail(path, "is not an ASCII STL (it does not start with 'solid'), and " + binary_size +
                   " (truncated or not an STL)");
  }
  if (bytes.find('\0') != std::string_view::npos) {
    fail(path, "starts like an ASCII STL but holds binary data; read as a binary STL, " +
                   binary_size + " (truncated?)");
  }
  return parse_ascii_stl(bytes, path);
}

// ---- Telling formats apart
// ------------------------------------------------------------------------

// The format the contents clearly are, or Unknown.
Format sniff(std::string_view bytes) {
  Lines lines(bytes);
  std::string_view line;
  while (lines.next(line)) {
    std::string_view rest = line.substr(0, line.find('#'));
    const std::string_view keyword = take_token(rest);
    if (keyword.empty()) continue;
    bool three_dimensional = true;
    if (keyword == "ply" && rest.find_first_not_of(" \t\r") == std::string_view::npos) {
      return Format::Ply;
    }
    if (parse_off_keyword(keyword, three_dimensional)) return Format::Off;
    break;
  }
  std::uint32_t count = 0;
  if (binary_stl_size_matches(bytes, count)) return Format::Stl;
  constexpr std::size_t kWindow = 1 << 16;
  const std::string_view window = bytes.substr(0, kWindow);
  if (window.find('\0') != std::string_view::npos) return Format::Unknown;
  if (starts_with_word(bytes, "solid") && window.find("facet") != std::string_view::npos) {
    return Format::Stl;
  }
  Lines obj_lines(window);
  while (obj_lines.next(line)) {
    const std::string_view keyword = take_token(line);
    if (keyword == "v" || keyword == "f") return Format::Obj;
  }
  return Format::Unknown;
}

// ---- From polygons to a mesh
// ----------------------------------------------------------------------

using Triangle = std::array<int, 3>;

// Polygons up to this many corners are triangulated by the max-min angle dynamic program (which
// also keeps a non-convex polygon from folding over itself); larger ones as a fan.
constexpr std::size_t kMaxOptimalPolygon = 64;

void triangulate_face(const std::vector<Point>& positions, std::vector<int> corners,
                      std::vector<Triangle>& triangles, LoadReport& report) {
  // Repeated consecutive corners (the last one repeating the first included) add nothing.
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  while (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();
  if (corners.size() < 3) {
    ++report.degenerate_faces_dropped;
    return;
  }
  const int n = static_cast<int>(corners.size());
  std::vector<Triangle> pieces;
  if (n == 3) {
    pieces.push_back({corners[0], corners[1], corners[2]});
  } else {
    ++report.polygons_triangulated;
    if (corners.size() <= kMaxOptimalPolygon) {
      HolePolygon polygon;
      for (const int c : corners) polygon.points.push_back(positions[c]);
      polygon.outside_normals.assign(corners.size(), Point(0.0, 0.0, 0.0));
      for (int i = 0; i < n; ++i) {
        for (int k = i + 1; k < n; ++k) {
          if (corners[i] == corners[k]) polygon.forbidden_chords.emplace_back(i, k);
        }
      }
      if (const auto optimal = triangulate_polygon(polygon, TriangulateOptions{})) {
        for (const auto& t : optimal->triangles) {
          pieces.push_back({corners[t[0]], corners[t[1]], corners[t[2]]});
        }
      }
    }
    if (pieces.empty()) {
      for (int c = 1; c + 1 < n; ++c) pieces.push_back({corners[0], corners[c], corners[c + 1]});
    }
  }
  bool dropped = false;
  for (const auto& t : pieces) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      dropped = true;
    } else {
      triangles.push_back(t);
    }
  }
  if (dropped) ++report.degenerate_faces_dropped;
}

// Removes triangles with the same corners in the same cyclic order as an earlier one.
std::size_t drop_duplicate_triangles(std::vector<Triangle>& triangles) {
  auto canonical = [](Triangle t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::vector<std::pair<Triangle, std::size_t>> sorted;
  sorted.reserve(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    sorted.emplace_back(canonical(triangles[i]), i);
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> duplicate(triangles.size(), 0);
  std::size_t count = 0;
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    if (sorted[i].first == sorted[i - 1].first) {
      duplicate[sorted[i].second] = 1;
      ++count;
    }
  }
  if (count == 0) return 0;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (!duplicate[i]) triangles[kept++] = triangles[i];
  }
  triangles.resize(kept);
  return count;
}

// One triangle's use of an undirected edge.
struct EdgeUse {
  std::uint64_t edge;  // smaller vertex index in the high half
  int triangle;
  bool forward;  // runs from the smaller vertex index to the larger
  bool operator<(const EdgeUse& other) const {
    return edge != other.edge ? edge < other.edge : triangle < other.triangle;
  }
};

std::vector<EdgeUse> edge_uses(const std::vector<Triangle>& triangles) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    for (int c = 0; c < 3; ++c) {
      const auto a = static_cast<std::uint32_t>(triangles[t][c]);
      const auto b = static_cast<std::uint32_t>(triangles[t][(c + 1) % 3]);
      uses.push_back({static_cast<std::uint64_t>(std::min(a, b)) << 32 | std::max(a, b), t, a < b});
    }
  }
  std::sort(uses.begin(), uses.end());
  return uses;
}

// Calls visit(first, last) for each run of uses of one edge.
template <class Visit>
void for_each_edge(const std::vector<EdgeUse>& uses, Visit&& visit) {
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].edge == uses[i].edge) ++j;
    visit(i, j);
    i = j;
  }
}

// Flips triangles so that neighbours across every edge with exactly two triangles use it in
// opposite directions; per connected piece, the orientation most triangles have wins. Returns
// the number flipped. Pieces that cannot be oriented (a Moebius strip) keep a conflict, which
// detach_non_manifold resolves.
std::size_t orient_consistently(std::vector<Triangle>& triangles) {
  const int count = static_cast<int>(triangles.size());
  const std::vector<EdgeUse> uses = edge_uses(triangles);
  // Up to three neighbours per triangle, and whether each must take the opposite orientation.
  std::vector<std::array<int, 3>> neighbour(triangles.size(), {-1, -1, -1});
  std::vector<std::array<bool, 3>> must_flip(triangles.size(), {false, false, false});
  std::vector<int> links(triangles.size(), 0);
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i != 2 || uses[i].triangle == uses[i + 1].triangle) return;
    const EdgeUse &a = uses[i], &b = uses[i + 1];
    const bool opposite = a.forward == b.forward;
    neighbour[a.triangle][links[a.triangle]] = b.triangle;
    must_flip[a.triangle][links[a.triangle]++] = opposite;
    neighbour[b.triangle][links[b.triangle]] = a.triangle;
    must_flip[b.triangle][links[b.triangle]++] = opposite;
  });
  std::vector<signed char> flip(triangles.size(), -1);
  std::vector<int> piece, queue;
  std::size_t flipped = 0;
  for (int seed = 0; seed < count; ++seed) {
    if (flip[seed] >= 0) continue;
    piece.clear();
    queue.assign(1, seed);
    flip[seed] = 0;
    while (!queue.empty()) {
      const int t = queue.back();
      queue.pop_back();
      piece.push_back(t);
      for (int l = 0; l < links[t]; ++l) {
        const int other = neighbour[t][l];
        if (flip[other] >= 0) continue;
        flip[other] = static_cast<signed char>(flip[t] ^ (must_flip[t][l] ? 1 : 0));
        queue.push_back(other);
      }
    }
    const auto marked = static_cast<std::size_t>(
        std::count_if(piece.begin(), piece.end(), [&](int t) { return flip[t] == 1; }));
    const signed char turn = 2 * marked > piece.size() ? 0 : 1;
    for (const int t : piece) {
      if (flip[t] != turn) continue;
      std::swap(triangles[t][1], triangles[t][2]);
      ++flipped;
    }
  }
  return flipped;
}

// Marks the triangles that must be kept apart so that every edge is used at most twice, in
// opposite directions: on each edge the first triangle and the first one after it running the
// other way stay; later ones (a third sheet on the edge, a fin) are detached.
std::vector<char> detach_non_manifold(const std::vector<EdgeUse>& uses, std::size_t triangles) {
  std::vector<char> detached(triangles, 0);
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    int kept = 0;
    bool first_forward = false;
    for (std::size_t k = i; k < j; ++k) {
      if (detached[uses[k].triangle]) continue;
      if (kept == 0) {
        first_forward = uses[k].forward;
        kept = 1;
      } else if (kept == 1 && uses[k].forward != first_forward) {
        kept = 2;
      } else {
        detached[uses[k].triangle] = 1;
      }
    }
  });
  return detached;
}

// OpenMesh cannot store a vertex whose closed fan of triangles is not all it has (two cones
// touching at their tips). Each such closed fan gets its own copy of the vertex, at the same
// position (appended to `positions`), so both surfaces stay closed. Fans with a boundary may
// share a vertex: that is a pinched boundary, which OpenMesh stores. Returns the copies made.
std::size_t split_closed_fans(std::vector<Triangle>& triangles, const std::vector<char>& detached,
                              std::vector<Point>& positions) {
  const std::vector<EdgeUse> uses = edge_uses(triangles);
  // Wedges are (triangle, corner) pairs; wedges at one vertex joined across shared edges form
  // that vertex's fans.
  std::vector<int> parent(3 * triangles.size());
  for (std::size_t w = 0; w < parent.size(); ++w) parent[w] = static_cast<int>(w);
  auto find = [&parent](int w) {
    while (parent[w] != w) w = parent[w] = parent[parent[w]];
    return w;
  };
  auto wedge = [&triangles](int t, int vertex) {
    const auto& c = triangles[t];
    return 3 * t + (c[0] == vertex ? 0 : c[1] == vertex ? 1 : 2);
  };
  std::vector<char> open(parent.size(), 0);  // the wedge lies on a boundary edge
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    int live[2], count = 0;
    for (std::size_t k = i; k < j; ++k) {
      if (!detached[uses[k].triangle] && count < 2) live[count++] = uses[k].triangle;
    }
    const int a = static_cast<int>(uses[i].edge >> 32);
    const int b = static_cast<int>(uses[i].edge & 0xFFFFFFFFu);
    if (count == 1) {
      open[wedge(live[0], a)] = open[wedge(live[0], b)] = 1;
    } else if (count == 2) {
      for (const int v : {a, b}) {
        parent[find(wedge(live[0], v))] = find(wedge(live[1], v));
      }
    }
  });
  // Fans per vertex: (vertex, fan root) pairs, and which fans are open.
  std::vector<std::pair<int, int>> fans;
  std::vector<char> fan_open(parent.size(), 0);
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    if (detached[t]) continue;
    for (int c = 0; c < 3; ++c) {
      const int root = find(3 * t + c);
      fans.emplace_back(triangles[t][c], root);
      if (open[3 * t + c]) fan_open[root] = 1;
    }
  }
  std::sort(fans.begin(), fans.end());
  fans.erase(std::unique(fans.begin(), fans.end()), fans.end());
  std::unordered_map<int, int> copy_of_fan;  // fan root -> its own vertex
  for (std::size_t i = 0; i < fans.size();) {
    std::size_t j = i;
    while (j < fans.size() && fans[j].first == fans[i].first) ++j;
    if (j - i > 1) {
      const bool any_open = std::any_of(fans.begin() + static_cast<std::ptrdiff_t>(i),
                                        fans.begin() + static_cast<std::ptrdiff_t>(j),
                                        [&](const auto& fan) { return fan_open[fan.second]; });
      bool original_taken = any_open;
      for (std::size_t k = i; k < j; ++k) {
        if (fan_open[fans[k].second]) continue;
        if (!original_taken) {
          original_taken = true;
          continue;
        }
        copy_of_fan[fans[k].second] = static_cast<int>(positions.size());
        positions.push_back(positions[fans[k].first]);
      }
    }
    i = j;
  }
  if (copy_of_fan.empty()) return 0;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    if (detached[t]) continue;
    for (int c = 0; c < 3; ++c) {
      const auto found = copy_of_fan.find(find(3 * t + c));
      if (found != copy_of_fan.end()) triangles[t][c] = found->second;
    }
  }
  return copy_of_fan.size();
}

Mesh assemble(const std::vector<Point>& positions, const std::vector<Triangle>& triangles,
              const std::vector<char>& detached, std::size_t original_vertices,
              LoadReport& report) {
  Mesh mesh;
  mesh.reserve(positions.size(), triangles.size() * 3 / 2 + 3, triangles.size());
  for (const auto& p : positions) mesh.add_vertex(p);
  auto add = [&mesh](const Triangle& t) {
    return mesh.add_face(VertexHandle(t[0]), VertexHandle(t[1]), VertexHandle(t[2])).is_valid();
  };
  std::vector<Triangle> refused;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (detached[t] || !add(triangles[t])) refused.push_back(triangles[t]);
  }
  // A face refused in one order can fit once the rest of its fans are in.
  for (std::size_t before = 0; !refused.empty() && refused.size() != before;) {
    before = refused.size();
    std::vector<Triangle> still;
    for (const auto& t : refused) {
      if (!add(t)) still.push_back(t);
    }
    refused = std::move(still);
  }
  // What still does not fit (an edge with a third face, a face turned against its neighbours)
  // is kept, on its own copies of its corners, so no data is lost.
  for (const auto& t : refused) {
    mesh.add_face(mesh.add_vertex(positions[t[0]]), mesh.add_vertex(positions[t[1]]),
                  mesh.add_vertex(positions[t[2]]));
    ++report.faces_detached;
  }
  for (std::size_t v = 0; v < original_vertices; ++v) {
    if (mesh.is_isolated(VertexHandle(static_cast<int>(v)))) ++report.isolated_vertices;
  }
  return mesh;
}

std::size_t count_duplicate_positions(const std::vector<Point>& positions) {
  std::unordered_set<PositionKey, PositionHash> seen;
  seen.reserve(positions.size());
  std::size_t duplicates = 0;
  for (const auto& p : positions) {
    if (!seen.insert(PositionKey(p)).second) ++duplicates;
  }
  return duplicates;
}

Mesh build_mesh(const Soup& soup, LoadReport& report) {
  std::vector<Triangle> triangles;
  triangles.reserve(soup.corners.size() / 3 + soup.face_count());
  std::vector<int> corners;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    corners.assign(soup.corners.begin() + static_cast<std::ptrdiff_t>(soup.face_begin(f)),
                   soup.corners.begin() + static_cast<std::ptrdiff_t>(soup.face_end[f]));
    triangulate_face(soup.positions, corners, triangles, report);
  }
  report.duplicate_faces_dropped = drop_duplicate_triangles(triangles);
  report.faces_flipped = orient_consistently(triangles);
  if (report.format != "stl") {
    report.duplicate_positions = count_duplicate_positions(soup.positions);
  }
  const std::vector<char> detached = detach_non_manifold(edge_uses(triangles), triangles.size());
  std::vector<Point> positions = soup.positions;
  report.vertices_split = split_closed_fans(triangles, detached, positions);
  return assemble(positions, triangles, detached, soup.positions.size(), report);
}

void add_warnings(LoadReport& report) {
  auto warn = [&report](std::size_t count, const std::string& text) {
    if (count) report.warnings.push_back(std::to_string(count) + " " + text);
  };
  warn(report.polygons_triangulated, "polygons with more than 3 corners were triangulated");
  warn(report.degenerate_faces_dropped,
       "degenerate faces (a vertex used twice, or fewer than 3 corners) were dropped");
  warn(report.duplicate_faces_dropped,
       "duplicate faces (the same corners as an earlier face) were dropped");
  warn(report.faces_flipped,
       "faces were flipped to agree with the orientation of their neighbours");
  warn(report.faces_detached, "non-manifold faces were kept on their own copies of their vertices");
  warn(report.vertices_split,
       "vertices where closed surfaces touch were split, one copy per surface");
  warn(report.duplicate_positions,
       "vertices have exactly the position of another vertex (kept apart: the surface may be "
       "cut open there)");
  warn(report.isolated_vertices, "vertices are used by no face (kept)");
  warn(report.elements_ignored, "line, point or curve elements were ignored (not surfaces)");
}

// ---- Files
// ----------------------------------------------------------------------------------------

std::string read_file(const fs::path& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a directory, not a mesh file");
  if (!fs::is_regular_file(status)) fail(path, "is not a regular file");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    fail(path, std::string("cannot be opened for reading (") + std::strerror(errno) + ")");
  }
  std::string bytes;
  const auto size = fs::file_size(path, ec);
  if (!ec) bytes.reserve(size);
  char buffer[1 << 16];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file)) > 0;) {
    bytes.append(buffer, got);
  }
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) fail(path, std::string("could not be read (") + std::strerror(error) + ")");
  return bytes;
}

// Writes vertices as "<prefix>x y z" and faces as "<face_prefix>a b c" with indices from `base`.
void write_lists(const Mesh& mesh, std::ostream& out, const char* vertex_prefix,
                 const char* face_prefix, int base) {
  char line[128];
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    std::snprintf(line, sizeof line, "%s%.17g %.17g %.17g\n", vertex_prefix, p[0], p[1], p[2]);
    out << line;
  }
  for (const auto f : mesh.faces()) {
    out << face_prefix;
    const char* separator = "";
    for (const auto v : mesh.fv_range(f)) {
      out << separator << v.idx() + base;
      separator = " ";
    }
    out << '\n';
  }
}

// OpenMesh's OFF and PLY writers store single precision; ours keep every bit of a double.
void write_mesh_text(const Mesh& mesh, const std::string& ext, std::ostream& out) {
  if (ext == ".obj") {
    out << "# written by holefill\n";
    write_lists(mesh, out, "v ", "f ", 1);
  } else if (ext == ".off") {
    out << "OFF\n" << mesh.n_vertices() << ' ' << mesh.n_faces() << " 0\n";
    write_lists(mesh, out, "", "3 ", 0);
  } else {
    out << "ply\nformat ascii 1.0\ncomment written by holefill\nelement vertex "
        << mesh.n_vertices()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
        << mesh.n_faces() << "\nproperty list uchar int vertex_indices\nend_header\n";
    write_lists(mesh, out, "", "3 ", 0);
  }
}

bool has_deleted_elements(const Mesh& mesh) {
  const auto live_vertices =
      static_cast<std::size_t>(std::distance(mesh.vertices().begin(), mesh.vertices().end()));
  const auto live_faces =
      static_cast<std::size_t>(std::distance(mesh.faces().begin(), mesh.faces().end()));
  return live_vertices != mesh.n_vertices() || live_faces != mesh.n_faces();
}

}  // namespace

const std::vector<std::string>& readable_extensions() {
  static const std::vector<std::string> extensions{".obj", ".off", ".ply", ".stl"};
  return extensions;
}

const std::vector<std::string>& writable_extensions() {
  static const std::vector<std::string> extensions{".obj", ".off", ".ply"};
  return extensions;
}

Mesh load_mesh_from_memory(const std::string& bytes, const fs::path& name, LoadReport* report) {
  LoadReport local;
  LoadReport& out = report ? *report : local;
  out = LoadReport{};
  // OpenMesh prints why add_face refuses a face; we count those faces and say so instead.
  omerr().disable();
  if (bytes.empty()) fail(name, "is empty");
  const std::string ext = lower_extension(name);
  const Format by_name = format_of_extension(ext);
  const Format by_content = sniff(bytes);
  Format format = by_name;
  if (by_content != Format::Unknown && by_content != by_name) {
    format = by_content;
    std::string upper = name_of(by_content);
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    out.warnings.push_back(by_name == Format::Unknown
                               ? "the extension '" + ext +
                                     "' is not a mesh format; the contents are " + upper +
                                     " and were read as such"
                               : "the contents are " + upper + ", not what the extension '" + ext +
                                     "' says; read as " + upper);
  }
  if (format == Format::Unknown) {
    fail(name, "unsupported file type '" + ext + "' (use .obj, .off, .ply or .stl)");
  }
  out.format = name_of(format);
  const std::string_view view(bytes);
  Soup soup;
  switch (format) {
    case Format::Obj:
      soup = parse_obj(view, name, out);
      break;
    case Format::Off:
      soup = parse_off(view, name);
      break;
    case Format::Ply:
      soup = parse_ply(view, name);
      break;
    case Format::Stl:
      soup = parse_stl(view, name);
      break;
    case Format::Unknown:
      break;
  }
  Mesh mesh = build_mesh(soup, out);
  if (mesh.n_faces() == 0) throw InvalidMeshError(name, "contains no faces");
  add_warnings(out);
  return mesh;
}

Mesh load_mesh(const fs::path& path, LoadReport* report) {
  return load_mesh_from_memory(read_file(path), path, report);
}

void save_mesh(const Mesh& mesh, const fs::path& path) {
  const std::string ext = lower_extension(path);
  const auto& writable = writable_extensions();
  if (std::find(writable.begin(), writable.end(), ext) == writable.end()) {
    throw FileError(path, "cannot write '" + ext + "' files (use .obj, .off or .ply)");
  }
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw FileError(path, "folder does not exist");
  if (fs::is_directory(path, ec)) throw FileError(path, "is a directory");
  // Indices in the file must count live elements only.
  Mesh compacted;
  const Mesh* source = &mesh;
  if (has_deleted_elements(mesh)) {
    compacted = mesh;
    compacted.garbage_collection();
    source = &compacted;
  }
  std::random_device seed;
  const fs::path temp =
      dir / ("." + path.stem().string() + ".partial-" + std::to_string(seed()) + ext);
  bool written = false;
  {
    std::ofstream out(temp, std::ios::binary);
    if (out) {
      write_mesh_text(*source, ext, out);
      out.flush();
      written = static_cast<bool>(out);
    }
  }
  if (!written) {
    fs::remove(temp, ec);
    throw FileError(path, "could not be written");
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw FileError(path, "could not be written (" + ec.message() + ")");
  }
}

}  // namespace holefill
