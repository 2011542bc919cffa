// Measuring a filled patch against the surface that was cut away: its distance to that surface,
// the shape of its triangles, its valences, its edge lengths against the surrounding mesh's, and
// how smoothly it meets the mesh across the hole's boundary.
#pragma once

#include <cstddef>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::quality {

// One filled hole, however it was filled: the hole's loop, the faces that fill it and the
// vertices the filling added, all as handles of the filled mesh.
struct FilledHole {
  std::vector<VertexHandle> boundary;
  std::vector<FaceHandle> faces;
  std::vector<VertexHandle> new_vertices;
};

// The closed mesh the holes were cut from, prepared for distance queries.
class Truth {
 public:
  explicit Truth(const Mesh& closed);
  // Only the given faces of `mesh` (a patch: the distance from the truth to a fill); the
  // diagonal is still the whole mesh's.
  Truth(const Mesh& mesh, const std::vector<FaceHandle>& faces);
  // Distance from p to the nearest triangle (infinite when there is none).
  double distance(const Point& p) const;
  // The nearest point to p on those triangles (p itself when there are none).
  Point nearest(const Point& p) const;
  double diagonal() const { return diagonal_; }

 private:
  struct Triangle {
    Point a, b, c, center;
    double radius;  // of a ball around `center` holding the triangle
  };
  std::vector<Triangle> triangles_;
  double diagonal_ = 0.0;
};

// Every measure is taken over all the holes of one filled mesh together. NaN where a measure
// has nothing to measure (no new vertices: no valence; no inner edges: no length ratio).
struct Quality {
  std::size_t new_vertices = 0;
  std::size_t faces = 0;
  // Distances of the patch's new vertices and face centroids to the truth, / bbox diagonal.
  double mean_distance = 0.0;
  double max_distance = 0.0;
  // Smallest interior angle of each patch triangle, degrees: 5th percentile and minimum.
  double min_angle_p5 = 0.0;
  double min_angle = 0.0;
  double valence6_share = 0.0;  // of new vertices, 0..1
  // Mean length of patch edges off the hole's boundary / mean length of the surrounding
  // mesh's edges at the boundary vertices.
  double edge_length_ratio = 0.0;
  // Angle between the normals of the two faces across each hole-boundary edge, degrees
  // (0: the patch continues the mesh flat).
  double mean_boundary_dihedral = 0.0;
  double max_boundary_dihedral = 0.0;
  // Largest angle between adjacent faces anywhere in the patch, degrees (near 180: a fold).
  double max_dihedral = 0.0;
};

Quality measure(const Mesh& filled, const std::vector<FilledHole>& holes, const Truth& truth);

}  // namespace holefill::quality
