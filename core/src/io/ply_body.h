// Reading the values of a PLY body record by record (ply_reader.cpp): ASCII, one record a line,
// or binary, the whole body or a part of it (two_parts.h).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>

#include "ply_header.h"
#include "text_scan.h"

namespace holefill::io {

// The lines of an ASCII body that one reading reads: all of them, or a part (two_parts.h).
struct BodyPart {
  std::size_t begin = 0, end = std::string_view::npos;  // bytes of the body, at line starts
  std::size_t lines_before = 0;                         // the body's lines before `begin`
  bool last = true;                                     // the part ends the body
};

// Reads the values of a PLY body record by record, ASCII (one record a line) or binary, refusing
// to read past its end or, in ASCII, past a record's line.
class PlyBody {
 public:
  PlyBody(std::string_view bytes, const PlyHeader& header, const std::filesystem::path& path,
          const BodyPart& part = {})
      : bytes_(bytes),
        lines_(bytes.substr(part.begin, part.end - std::min(part.end, part.begin))),
        encoding_(header.encoding),
        path_(path),
        line_offset_(header.header_lines + part.lines_before),
        part_begin_(part.begin),
        last_part_(part.last) {}

  // Starts record `index` of the `count` records of `element`; false when a part that does not
  // end the body has no more lines.
  bool begin_record(const std::string& element, unsigned long long index,
                    unsigned long long count) {
    element_ = &element;
    index_ = index;
    count_ = count;
    record_line_ = 0;
    if (encoding_ != PlyEncoding::Ascii) return true;
    if (!lines_.next(record_)) {
      if (!last_part_) return false;
      fail(path_, "ends before " + where() + " (truncated?)");
    }
    record_line_ = line_number();
    return true;
  }

  // Ends the record: in ASCII, its line must hold no more values.
  void end_record() {
    if (encoding_ != PlyEncoding::Ascii) return;
    skip_blanks(record_);
    if (!record_.empty()) {
      fail(path_, where() + " has more values than the header's properties give it (" +
                      quoted(record_) + " left over)");
    }
  }

  // The current record, for messages (made only when one is needed: once per record was a
  // large part of reading a big binary file).
  std::string where() const {
    return (record_line_ ? at_line(record_line_) : std::string()) + "'" + *element_ + "' element " +
           std::to_string(index_) + " of " + std::to_string(count_);
  }

  double read(PlyType type) {
    return encoding_ == PlyEncoding::Ascii ? read_text(type) : read_binary(type);
  }

  // Bytes left (to the body's end, whatever part is read); for ASCII, an upper bound on the
  // values left.
  std::size_t remaining() const {
    return encoding_ == PlyEncoding::Ascii
               ? record_.size() + 1 + bytes_.size() - part_begin_ - lines_.offset()
               : bytes_.size() - position_;
  }

  // What follows the last record, for a warning: "N bytes" (binary), or the number of lines
  // (ASCII: of this part).
  std::string leftover_bytes() const {
    return remaining() ? std::to_string(remaining()) + " bytes" : std::string();
  }
  std::size_t lines_read() const { return lines_.number(); }
  std::size_t leftover_lines() {
    std::size_t count = 0;
    for (std::string_view line; lines_.next(line);) ++count;
    return count;
  }

 private:
  std::size_t line_number() const { return line_offset_ + lines_.number(); }

  template <class T>
  static double load(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof value);
    return static_cast<double>(value);
  }

  double read_binary(PlyType type) {
    const std::size_t size = size_of(type);
    if (bytes_.size() - position_ < size) {
      fail(path_, "ends in the middle of " + where() + " (truncated?)");
    }
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, size);
    position_ += size;
    const bool swap =
        (encoding_ == PlyEncoding::BinaryBigEndian) != (std::endian::native == std::endian::big);
    if (swap) std::reverse(raw, raw + size);
    switch (type) {
      case PlyType::Int8:
        return load<std::int8_t>(raw);
      case PlyType::UInt8:
        return load<std::uint8_t>(raw);
      case PlyType::Int16:
        return load<std::int16_t>(raw);
      case PlyType::UInt16:
        return load<std::uint16_t>(raw);
      case PlyType::Int32:
        return load<std::int32_t>(raw);
      case PlyType::UInt32:
        return load<std::uint32_t>(raw);
      case PlyType::Float32:
        return load<float>(raw);
      case PlyType::Float64:
        return load<double>(raw);
    }
    return 0.0;
  }

  // Numbers are read in place (take_double, take_integer); the token is cut out only for a
  // message.
  double read_text(PlyType type) {
    const std::string_view unread = record_;
    if (is_integer_type(type)) {
      long long value = 0;
      if (!take_integer(record_, value)) refuse_text_value(unread, "expected a whole number");
      if (!fits(value, type)) {
        fail(path_,
             where() + ": " + quoted(first_token(unread)) + " does not fit the property's type");
      }
      return static_cast<double>(value);
    }
    double value = 0.0;
    if (!take_double(record_, value)) refuse_text_value(unread, "expected a number");
    // What the header says the value is: a float property holds a float, as in a binary file.
    if (type != PlyType::Float32) return value;
    if (!(std::abs(value) <= std::numeric_limits<float>::max())) {
      return std::isnan(value) ? value : std::copysign(HUGE_VAL, value);  // as a float reads
    }
    return static_cast<double>(static_cast<float>(value));
  }

  static std::string_view first_token(std::string_view text) { return take_token(text); }

  [[noreturn]] void refuse_text_value(std::string_view unread, const char* expected) const {
    const std::string_view token = first_token(unread);
    if (token.empty()) {
      fail(path_, where() + " has fewer values than the header's properties give it");
    }
    fail(path_, where() + ": " + expected + ", got " + quoted(token));
  }

  std::string_view bytes_;
  ContentLines lines_;       // ASCII: the lines of the part read
  std::string_view record_;  // ASCII: what is left of the current record's line
  PlyEncoding encoding_;
  const std::filesystem::path& path_;
  std::size_t line_offset_;
  std::size_t part_begin_;
  bool last_part_;
  std::size_t position_ = 0;              // binary: the next byte
  const std::string* element_ = nullptr;  // the current record's element, index and line
  unsigned long long index_ = 0, count_ = 0;
  std::size_t record_line_ = 0;
};

}  // namespace holefill::io
