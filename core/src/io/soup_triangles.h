// The first of build_mesh's steps (soup_to_mesh.h): the polygons a file describes cut into
// triangles. Triangles stay as they are; polygons of up to 64 corners are triangulated by the
// max-min angle dynamic program (which keeps a non-convex polygon from folding over itself),
// larger ones as a fan; faces with fewer than three distinct corners are dropped.
#pragma once

#include <vector>

#include "holefill/io.h"
#include "mesh_from_triangles.h"
#include "soup.h"

namespace holefill::io {

// The soup's polygons as triangles (by soup position), with, when tracked, the soup corners each
// was made of and the polygon each came from.
struct SoupTriangles {
  std::vector<Triangle> triangles;
  std::vector<Triangle> corners;  // when tracked
  std::vector<int> face;          // when tracked
};

// The soup's polygons as triangles, in the order of the faces; on two threads (`two`), each
// triangulates half of the faces, and the second half's triangles follow the first's. Counts the
// polygons triangulated and the faces dropped in `report`.
SoupTriangles triangulate_soup(const Soup& soup, bool track_origins, bool track_corners, bool two,
                               LoadReport& report);

}  // namespace holefill::io
