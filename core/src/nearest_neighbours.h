// The restricted search's nearest boundary neighbours (triangulate_restricted.cpp), found with a
// k-d tree (nanoflann) instead of comparing every pair of vertices.
#pragma once

#include <vector>

#include "holefill/mesh.h"

namespace holefill::detail {

// For each point, the indices of its `count` nearest other points (all of them when there are
// fewer), nearest first, equal distances in index order: exactly what sorting the squared
// distances (p[i] - p[j]).sqrnorm() to every other point by (distance, index) gives.
std::vector<std::vector<int>> nearest_neighbours(const std::vector<Point>& points, int count);

}  // namespace holefill::detail
