#include "soup_triangles.h"

#include <algorithm>

#include "holefill/triangulate.h"
#include "huge_pages.h"
#include "two_parts.h"
#include "two_threads.h"

namespace holefill::io {
namespace {

// Polygons up to this many corners are triangulated by the max-min angle dynamic program (which
// also keeps a non-convex polygon from folding over itself); larger ones as a fan.
constexpr std::size_t kMaxOptimalPolygon = 64;

// The triangles (by positions in ks) that cut the polygon of soup corners ks, more than three
// with no two consecutive ones at one vertex.
std::vector<Triangle> polygon_pieces(const Soup& soup, const std::vector<int>& ks) {
  auto vertex = [&soup](int k) { return soup.corners[k]; };
  const int n = static_cast<int>(ks.size());
  std::vector<Triangle> pieces;
  if (ks.size() <= kMaxOptimalPolygon) {
    HolePolygon polygon;
    for (const int k : ks) polygon.points.push_back(soup.positions[vertex(k)]);
    polygon.outside_normals.assign(ks.size(), Point(0.0, 0.0, 0.0));
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (vertex(ks[i]) == vertex(ks[j])) polygon.forbidden_chords.emplace_back(i, j);
      }
    }
    if (const auto optimal = triangulate_polygon(polygon, TriangulateOptions{})) {
      for (const auto& t : optimal->triangles) pieces.push_back({t[0], t[1], t[2]});
    }
  }
  if (pieces.empty()) {
    for (int c = 1; c + 1 < n; ++c) pieces.push_back({0, c, c + 1});
  }
  return pieces;
}

// Triangulates the soup's polygon f: each triangle's corners (soup positions) go to `triangles`
// and, with `corners`, the soup corners (indices into soup.corners) they came from to `corners`.
void triangulate_face(const Soup& soup, std::size_t f, std::vector<int>& ks,
                      std::vector<Triangle>& triangles, std::vector<Triangle>* corners,
                      LoadReport& report) {
  ks.clear();  // the polygon's soup corners (the caller's, to spare an allocation per face)
  for (std::size_t k = soup.face_begin(f); k < soup.face_end[f]; ++k) {
    ks.push_back(static_cast<int>(k));
  }
  auto vertex = [&soup](int k) { return soup.corners[k]; };
  // Repeated consecutive corners (the last one repeating the first included) add nothing.
  ks.erase(std::unique(ks.begin(), ks.end(), [&](int a, int b) { return vertex(a) == vertex(b); }),
           ks.end());
  while (ks.size() > 1 && vertex(ks.front()) == vertex(ks.back())) ks.pop_back();
  if (ks.size() < 3) {
    ++report.degenerate_faces_dropped;
    return;
  }
  if (ks.size() == 3) {  // most faces: nothing to cut
    triangles.push_back({vertex(ks[0]), vertex(ks[1]), vertex(ks[2])});
    if (corners) corners->push_back({ks[0], ks[1], ks[2]});
    return;
  }
  ++report.polygons_triangulated;
  const std::vector<Triangle> pieces = polygon_pieces(soup, ks);
  bool dropped = false;
  for (const auto& p : pieces) {
    const Triangle t{vertex(ks[p[0]]), vertex(ks[p[1]]), vertex(ks[p[2]])};
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      dropped = true;
      continue;
    }
    triangles.push_back(t);
    if (corners) corners->push_back({ks[p[0]], ks[p[1]], ks[p[2]]});
  }
  if (dropped) ++report.degenerate_faces_dropped;
}

// Triangulates the soup's faces [begin, end) onto the end of `into`, counting in `report`.
void triangulate_faces(const Soup& soup, std::size_t begin, std::size_t end, bool track_origins,
                       bool track_corners, SoupTriangles& into, LoadReport& report) {
  std::vector<int> polygon;  // the polygon's soup corners, one allocation for all faces
  for (std::size_t f = begin; f < end; ++f) {
    triangulate_face(soup, f, polygon, into.triangles, track_corners ? &into.corners : nullptr,
                     report);
    if (track_origins) into.face.resize(into.triangles.size(), static_cast<int>(f));
  }
}

// Gives `into` room for the triangles of the soup's faces [begin, end): a polygon of k corners
// makes k - 2 triangles at most, so a mesh of triangles fills the first `likely` (the room allows
// for any polygons).
void reserve_triangles(const Soup& soup, std::size_t begin, std::size_t end, bool track_origins,
                       bool track_corners, SoupTriangles& into) {
  const std::size_t faces = end - begin;
  const std::size_t corners = begin == end ? 0 : soup.face_end[end - 1] - soup.face_begin(begin);
  const std::size_t room = corners / 3 + faces;
  const std::size_t likely = corners - std::min(corners, 2 * faces);
  reserve_on_huge_pages(into.triangles, room, likely);
  if (track_origins) reserve_on_huge_pages(into.face, room, likely);
  if (track_corners) reserve_on_huge_pages(into.corners, room, likely);
}

}  // namespace

SoupTriangles triangulate_soup(const Soup& soup, bool track_origins, bool track_corners, bool two,
                               LoadReport& report) {
  SoupTriangles first, second;
  const std::size_t faces = soup.face_count(), middle = two ? faces / 2 : faces;
  reserve_triangles(soup, 0, faces, track_origins, track_corners, first);
  LoadReport second_report;
  run_both(
      two, [&] { triangulate_faces(soup, 0, middle, track_origins, track_corners, first, report); },
      [&] {
        if (middle == faces) return;
        reserve_triangles(soup, middle, faces, track_origins, track_corners, second);
        triangulate_faces(soup, middle, faces, track_origins, track_corners, second, second_report);
      });
  report.polygons_triangulated += second_report.polygons_triangulated;
  report.degenerate_faces_dropped += second_report.degenerate_faces_dropped;
  append_and_free(first.triangles, second.triangles);
  append_and_free(first.corners, second.corners);
  append_and_free(first.face, second.face);
  return first;
}

}  // namespace holefill::io
