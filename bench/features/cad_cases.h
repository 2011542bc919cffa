// The CAD set of the sharp-feature evaluation (README.md): each case is a closed mesh and one hole
// cut out of it on purpose, across a straight crease, a corner where three faces meet, a
// cylinder's rim, a fillet (where no crease should appear), or a flat face (the control).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cut_holes.h"
#include "holefill/mesh.h"

namespace holefill::features {

struct CadCase {
  std::string name;
  std::string what;  // one line for the tables
  Mesh closed;
  Point center;   // of the ball whose faces are cut (quality::cut_ball)
  double radius;  // of that ball
};

// The generated cases, in the order of the tables.
std::vector<CadCase> generated_cases();

// A closed real mesh's cases: a hole across a crease (at a vertex on exactly two sharp edges,
// dihedral above `sharp_degrees`) and one across a corner (a vertex on three or more), each a ball
// of `radius_edges` mean edge lengths, picked by a generator seeded with `seed` among the
// vertices where such a ball cuts a clean disk. `name` prefixes the case names. Fewer cases
// when the mesh has no such vertex.
std::vector<CadCase> real_cases(const std::string& name, const Mesh& closed, double sharp_degrees,
                                double radius_edges, unsigned seed);

// Splits every edge longer than `longest` at its midpoint (the longest first) until none is:
// the same surface with its creases, sampled densely enough to cut holes from. A CAD export's
// long thin triangles spanning whole faces become a hole's neighbourhood of several vertices.
void split_long_edges(Mesh& mesh, double longest);

// Flips edges between two faces in one plane (within 1e-4 radians: STL stores floats) until each
// such pair is Delaunay (the angles opposite the edge sum to at most 180 degrees), at most 50
// rounds: better triangles, the same surface, its creases untouched. After split_long_edges, which
// leaves fans of thin triangles.
void flip_flat_edges_to_delaunay(Mesh& mesh);

// The case's cut (cut_ball), or nothing with `problem` set.
std::optional<quality::CutMesh> cut_case(const CadCase& c, std::string* problem = nullptr);

}  // namespace holefill::features
