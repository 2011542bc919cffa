// Writing numbers and vertex lines of text mesh files: the shortest text that reads back to the
// same value (std::to_chars), so a round trip keeps every bit. Shared by the writers.
#pragma once

#include <charconv>
#include <string>

#include "holefill/mesh.h"

namespace holefill::io {

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

// Vertices as "<prefix>x y z", then whatever `after` appends to the line.
template <class After>
void append_vertices(const Mesh& mesh, std::string& out, const char* prefix, After&& after) {
  for (const auto v : mesh.vertices()) {
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

// Faces as "<prefix>a b c" with vertex indices counted from `base`, then whatever `after`
// appends to the line.
template <class After>
void append_faces(const Mesh& mesh, std::string& out, const char* prefix, int base, After&& after) {
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
  }
}

}  // namespace holefill::io
