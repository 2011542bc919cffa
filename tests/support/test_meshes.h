// Meshes made in code for the tests: closed shapes with known topology, and ways to cut holes.
#pragma once

#include <functional>
#include <random>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/triangulate.h"

namespace holefill::testing {

// A unit sphere: an icosahedron subdivided `levels` times, projected to the sphere.
Mesh make_icosphere(int levels);

// Adds a copy of `part`, moved by `offset`, to `mesh` (its vertices and faces after the mesh's).
void append_mesh(Mesh& mesh, const Mesh& part, const Point& offset);

// A height field z = height(x, y) over [0,1]^2 sampled on an n x n vertex grid.
Mesh make_grid(int n, const std::function<double(double, double)>& height);

// A flat n x n grid of squares with every third square of every third row left out: about
// (n/3)^2 holes of 4 edges.
Mesh grid_with_square_holes(int n);

// An icosphere (3 levels) with a wavy cap cut out around +z and a small hole at -z.
Mesh sphere_with_two_holes();

// A copy of `mesh` without the faces for which `remove(face centroid)` is true; vertices keep
// their indices (unreferenced ones stay, isolated).
Mesh without_faces(const Mesh& mesh, const std::function<bool(const Point&)>& remove);

// The same, deciding by the face's centroid and unit normal.
Mesh without_faces_where(const Mesh& mesh,
                         const std::function<bool(const Point&, const Point&)>& remove);

// A random simple polygon: points on a wavy, noisy loop around the z axis (radius ~1).
std::vector<Point> random_loop(int n, std::mt19937& rng, double noise = 0.2, double waviness = 0.3);

// A hole's polygon on a wavy, noisy loop of n points (random_loop from this seed), with the
// surrounding surface leaning outwards as around a hole in a curved mesh: what the benchmarks
// (and the tests that compare searches) triangulate.
HolePolygon wavy_hole(int n, unsigned seed = 42);

// Every vertex position and every face's vertex list of `before` is present, unchanged, at
// the same index in `after`.
bool original_part_unchanged(const Mesh& before, const Mesh& after);

// Every edge has at most two faces, used in opposite directions (OpenMesh stores only such
// meshes, so this checks the halfedge links), and every vertex has one fan of faces.
bool is_oriented_manifold(const Mesh& mesh);

}  // namespace holefill::testing
