// Mesh files as text or bytes, in every format and encoding the readers take, for the
// robustness suites (bad files, reader defects).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::testing {

// A closed tetrahedron, faces turned outwards.
inline const std::vector<Point> kTetraPoints{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
inline const std::vector<std::vector<int>> kTetraFaces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// The body OFF and ASCII PLY share after their headers: "x y z" lines, then "n i j k" lines.
inline void put_points_and_polygons(std::ostringstream& text, const std::vector<Point>& points,
                                    const std::vector<std::vector<int>>& faces) {
  text.precision(17);
  for (const auto& p : points) text << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& f : faces) {
    text << f.size();
    for (const int c : f) text << ' ' << c;
    text << '\n';
  }
}

inline std::string off_text(const std::vector<Point>& points,
                            const std::vector<std::vector<int>>& faces) {
  std::ostringstream text;
  text << "OFF\n" << points.size() << ' ' << faces.size() << " 0\n";
  put_points_and_polygons(text, points, faces);
  return text.str();
}

template <class T>
inline void put(std::string& bytes, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
  bytes.append(raw, sizeof(T));
}

inline std::string binary_ply(const std::vector<Point>& points,
                              const std::vector<std::vector<int>>& faces, bool big_endian) {
  std::string bytes =
      std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
      " 1.0\ncomment made by bad_files_test\nelement vertex " + std::to_string(points.size()) +
      "\nproperty float x\nproperty float y\nproperty float z\n"
      "property uchar red\nelement face " +
      std::to_string(faces.size()) +
      "\nproperty list uchar int vertex_indices\nproperty float quality\n"
      "end_header\n";
  for (const auto& p : points) {
    for (int axis = 0; axis < 3; ++axis) put(bytes, static_cast<float>(p[axis]), big_endian);
    put(bytes, static_cast<std::uint8_t>(200), big_endian);
  }
  for (const auto& f : faces) {
    put(bytes, static_cast<std::uint8_t>(f.size()), big_endian);
    for (const int c : f) put(bytes, static_cast<std::int32_t>(c), big_endian);
    put(bytes, 0.5f, big_endian);
  }
  return bytes;
}

inline std::string ascii_ply(const std::vector<Point>& points,
                             const std::vector<std::vector<int>>& faces) {
  std::ostringstream text;
  text << "ply\nformat ascii 1.0\nelement vertex " << points.size()
       << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << faces.size()
       << "\nproperty list uchar int vertex_indices\nend_header\n";
  put_points_and_polygons(text, points, faces);
  return text.str();
}

inline std::string binary_stl(const std::vector<Point>& points,
                              const std::vector<std::vector<int>>& faces,
                              std::uint32_t claimed_count) {
  std::string bytes(80, ' ');
  bytes.replace(0, 11, "binary test");
  put(bytes, claimed_count, false);
  for (const auto& f : faces) {
    for (int i = 0; i < 3; ++i) put(bytes, 0.0f, false);
    for (const int c : f) {
      for (int axis = 0; axis < 3; ++axis) put(bytes, static_cast<float>(points[c][axis]), false);
    }
    put(bytes, static_cast<std::uint16_t>(0), false);
  }
  return bytes;
}

inline std::string ascii_stl(const std::vector<Point>& points,
                             const std::vector<std::vector<int>>& faces) {
  std::ostringstream text;
  text << "solid tetra\n";
  for (const auto& f : faces) {
    text << "  facet normal 0 0 0\n    outer loop\n";
    for (const int c : f) {
      text << "      vertex " << points[c][0] << ' ' << points[c][1] << ' ' << points[c][2] << '\n';
    }
    text << "    endloop\n  endfacet\n";
  }
  text << "endsolid tetra\n";
  return text.str();
}

}  // namespace holefill::testing
