// Dirty meshes, generated: what exporters, scanners and STL soups hand a user.
// Each generator returns a soup (points and faces as a file lists them) whose dirt is known
// exactly, so that the tests can assert what stitching, pinch filling, component removal and
// border classification must make of it.
#pragma once

#include <array>
#include <functional>
#include <random>

#include "robust_test_util.h"

namespace holefill::testing {

// An icosphere of radius 1 (test_meshes.h) as a soup.
Soup sphere_soup(int levels);

// A bumpy height field z = 0.15 sin(5x) cos(4y) over [0,1]^2 with n x n vertices.
Soup terrain_soup(int n);

// The upper part (z > bottom) of an icosphere: a dome whose rim is at height `bottom`.
Soup dome_soup(int levels, double bottom);

// The soup without the faces whose centroid `remove` picks; points stay (maybe unused).
Soup without(Soup soup, const std::function<bool(const Point&)>& remove);

// Both soups in one, b's indices shifted after a's points.
Soup append(Soup a, const Soup& b);

// Cuts the soup apart between the faces whose centroid `side` picks and the others: every
// point used on both sides (and picked by `on_cut`, when given: a crack rather than a cut) gets
// a copy (appended) for the picked faces, moved by a random offset of length `gap` (0: at exactly
// the same place). Returns the number of copies made.
std::size_t cut_apart(Soup& soup, const std::function<bool(const Point&)>& side, double gap,
                      std::mt19937& rng, const std::function<bool(const Point&)>& on_cut = {});

// An axis-aligned cube [0,1]^3 exported face by face: six n x n grids, each with its own points
// (so every cube edge is a seam and every corner is three points at one place).
Soup box_of_separate_faces(int n);
// The same with sides of their own resolution (points per grid row, in the order z = 0, z = 1,
// y = 0, y = 1, x = 0, x = 1): where two sides of different resolutions meet, one side's points
// lie inside the other's edges (T-junctions), as when a CAD part's faces are tessellated apart.
Soup box_of_separate_faces(const std::array<int, 6>& points_per_side);

// The centroid of a soup face.
Point face_centroid(const Soup& soup, const std::vector<int>& face);

// Removes from a soup the faces within `radius` of `centre` (a hole in the surface there).
Soup with_hole(Soup soup, const Point& centre, double radius);

}  // namespace holefill::testing
