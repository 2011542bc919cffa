// Writing numbers and vertex lines of text mesh files: the shortest text that reads back to the
// same value (std::to_chars), so a round trip keeps every bit. Shared by the writers.
#pragma once

#include <algorithm>
#include <charconv>
#include <string>
#include <string_view>
#include <vector>

#include "../parallel_indices.h"
#include "holefill/mesh.h"
#include "holefill/output_file.h"

namespace holefill::io {

// A file's bytes as a writer makes them: appended to `text`, and handed on to the ByteWriter in
// pieces of about a megabyte as records end, so that a big file never exists whole in memory
// (its text was a sixth of the peak of filling a 1.4M-face mesh). Runs of records (vertices,
// faces) are formatted in blocks, on up to `threads` threads at once, and handed on in order.
class PieceOut {
 public:
  explicit PieceOut(const ByteWriter& write, unsigned threads = 1)
      : write_(write), threads_(std::max(1u, threads)) {
    text.reserve(kPieceBytes + kPieceBytes / 4);
  }
  // After each record: hands the text on once it is a piece's size.
  void end_record() {
    if (text.size() >= kPieceBytes) flush();
  }
  // Hands on what is left (at the end).
  void flush() {
    if (text.empty()) write_(text);  // the end of a file made in blocks
    hand_on(text);
    text.clear();
  }
  // Hands on, after the text so far, the records 0 .. count - 1, which format(text, first, last)
  // appends to `text` for records [first, last). The blocks of records are formatted `threads` at
  // a time, each on a thread of its own (none is started for one), into texts that are reused,
  // and handed on in pieces of at most a megabyte.
  template <class Format>
  void records(std::size_t count, Format&& format) {
    if (threads_ == 1 || count <= kRecordsPerBlock) {
      for (std::size_t first = 0; first < count; first += kRecordsPerBlock) {
        format(text, first, std::min(count, first + kRecordsPerBlock));
        const std::size_t whole = text.size() / kPieceBytes * kPieceBytes;
        hand_on(std::string_view(text).substr(0, whole));
        text.erase(0, whole);
      }
      return;
    }
    flush();
    blocks_.resize(threads_);
    for (std::size_t round = 0; round < count; round += threads_ * kRecordsPerBlock) {
      detail::for_each_index(threads_, threads_, [&](std::size_t k) {
        const std::size_t first = std::min(count, round + k * kRecordsPerBlock);
        blocks_[k].clear();
        format(blocks_[k], first, std::min(count, first + kRecordsPerBlock));
      });
      for (const std::string& block : blocks_) hand_on(block);
    }
  }

  std::string text;

 private:
  static constexpr std::size_t kPieceBytes = std::size_t{1} << 20;
  static constexpr std::size_t kRecordsPerBlock = std::size_t{1} << 15;
  // Hands on `bytes` in pieces of at most kPieceBytes (none when empty).
  void hand_on(std::string_view bytes) {
    for (; !bytes.empty(); bytes.remove_prefix(std::min(bytes.size(), kPieceBytes))) {
      write_(bytes.substr(0, kPieceBytes));
    }
  }

  const ByteWriter& write_;
  unsigned threads_;
  std::vector<std::string> blocks_;
};

inline void append_number(std::string& out, double value) {
  char text[32];
  out.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

inline void append_number(std::string& out, float value) {
  char text[32];
  out.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

inline void append_number(std::string& out, long long value) {
  char text[24];
  out.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

// Vertices [first, last) as "<prefix>x y z", then whatever `after` appends to the line.
template <class After>
void append_vertices(const Mesh& mesh, std::string& out, std::size_t first, std::size_t last,
                     const char* prefix, After&& after) {
  for (std::size_t i = first; i < last; ++i) {
    const VertexHandle v(static_cast<int>(i));
    const Point& p = mesh.point(v);
    out += prefix;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis) out += ' ';
      append_number(out, p[axis]);
    }
    after(v);
    out += '\n';
  }
}

// Faces [first, last) as "<prefix>a b c" with vertex indices counted from `base`, then whatever
// `after` appends to the line.
template <class After>
void append_faces(const Mesh& mesh, std::string& out, std::size_t first, std::size_t last,
                  const char* prefix, int base, After&& after) {
  for (std::size_t i = first; i < last; ++i) {
    const FaceHandle f(static_cast<int>(i));
    out += prefix;
    const char* separator = "";
    for (const auto v : mesh.fv_range(f)) {
      out += separator;
      append_number(out, static_cast<long long>(v.idx()) + base);
      separator = " ";
    }
    after(f);
    out += '\n';
  }
}

}  // namespace holefill::io
