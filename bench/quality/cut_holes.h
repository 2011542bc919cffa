// Cutting holes out of a closed mesh, so that a filled patch can be compared with the surface
// that was there: each hole is a geodesic disk (faces whose centroid lies within a radius of a
// seed vertex, distances along edges), cleaned up until its boundary is one simple loop.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::quality {

struct CutHole {
  VertexHandle seed;
  double radius = 0.0;                       // absolute, along edges
  std::vector<FaceHandle> removed_faces;     // faces of the closed mesh
  std::vector<VertexHandle> inner_vertices;  // vertices all of whose faces were removed
};

struct CutMesh {
  // The closed mesh's vertices (same indices; the holes' inner vertices stay, unused) and the
  // faces that were not removed.
  Mesh mesh;
  std::vector<CutHole> holes;  // in the order of the requested radii
};

// Cuts one hole per radius (radii in units of the closed mesh's mean edge length). Seeds are
// drawn by a generator seeded with `seed`, so the same arguments cut the same holes on every
// platform; a seed whose disk is not a clean disk (or comes near an earlier hole) is redrawn.
// Returns nothing, with `problem` set, when some hole cannot be placed.
std::optional<CutMesh> cut_holes(const Mesh& closed, const std::vector<double>& radii,
                                 unsigned seed, std::string* problem = nullptr);

// Cuts one hole: the edge-connected faces whose centroid lies within `radius` (straight-line
// distance) of `center`, grown from the face whose centroid is nearest, cleaned up into a disk
// as cut_holes does; the hole's seed is a corner of that face. Holes across a mesh's creases and
// corners are placed this way. Returns nothing, with `problem` set, when the cut is not one disk
// bounded by one simple loop.
std::optional<CutMesh> cut_ball(const Mesh& closed, const Point& center, double radius,
                                std::string* problem = nullptr);

// Mean edge length of a mesh.
double mean_edge_length(const Mesh& mesh);

}  // namespace holefill::quality
