// Writing numbers and vertex lines of text mesh files: the shortest text that reads back to the
// same value (std::to_chars), so a round trip keeps every bit. Shared by the writers.
#pragma once

#include <charconv>
#include <string>

#include "holefill/mesh.h"
#include "holefill/output_file.h"

namespace holefill::io {

// A file's bytes as a writer makes them: appended to `text`, and handed on to the ByteWriter in
// pieces of about a megabyte as records end, so that a big file never exists whole in memory
// (its text was a sixth of the peak of filling a 1.4M-face mesh).
class PieceOut {
 public:
  explicit PieceOut(const ByteWriter& write) : write_(write) {
    text.reserve(kPieceBytes + kPieceBytes / 4);
  }
  // After each record: hands the text on once it is a piece's size.
  void end_record() {
    if (text.size() >= kPieceBytes) flush();
  }
  // Hands on what is left (at the end).
  void flush() {
    write_(text);
    text.clear();
  }

  std::string text;

 private:
  static constexpr std::size_t kPieceBytes = std::size_t{1} << 20;
  const ByteWriter& write_;
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

// Reserves room for the vertex and face records still to come, `vertex_values` and `face_values`
// numbers each, at the most a number takes (24 characters and a separator; 8 bytes in binary),
// so that a big file's bytes are not copied into a string twice the size each time it fills
// (the old string and the new were both held: a third of the peak of filling a 1.4M-face mesh).
// Room not written to takes no memory.
inline void reserve_records(std::string& out, const Mesh& mesh, std::size_t vertex_values,
                            std::size_t face_values) {
  out.reserve(out.size() + mesh.n_vertices() * (25 * vertex_values + 1) +
              mesh.n_faces() * (25 * face_values + 1));
}

// Vertices as "<prefix>x y z", then whatever `after` appends to the line; `line_done` is called
// after each line.
template <class After, class LineDone>
void append_vertices(const Mesh& mesh, std::string& out, const char* prefix, After&& after,
                     LineDone&& line_done) {
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    out += prefix;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis) out += ' ';
      append_number(out, p[axis]);
    }
    after(v);
    out += '\n';
    line_done();
  }
}

template <class After>
void append_vertices(const Mesh& mesh, std::string& out, const char* prefix, After&& after) {
  append_vertices(mesh, out, prefix, after, [] {});
}

// Faces as "<prefix>a b c" with vertex indices counted from `base`, then whatever `after`
// appends to the line; `line_done` is called after each line.
template <class After, class LineDone>
void append_faces(const Mesh& mesh, std::string& out, const char* prefix, int base, After&& after,
                  LineDone&& line_done) {
  for (const auto f : mesh.faces()) {
    out += prefix;
    const char* separator = "";
    for (const auto v : mesh.fv_range(f)) {
      out += separator;
      append_number(out, static_cast<long long>(v.idx()) + base);
      separator = " ";
    }
    after(f);
    out += '\n';
    line_done();
  }
}

template <class After>
void append_faces(const Mesh& mesh, std::string& out, const char* prefix, int base, After&& after) {
  append_faces(mesh, out, prefix, base, after, [] {});
}

}  // namespace holefill::io
