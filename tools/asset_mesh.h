// The small mesh type of holefill-make-assets (no dependency on holefill itself, so that the assets
// do not change with the library): points, faces, their edges and pieces, and plain OBJ files.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace make_assets {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(Vec3 a) { return (1.0 / norm(a)) * a; }

using Face = std::array<int, 3>;  // counter-clockwise seen from outside

struct Mesh {
  std::vector<Vec3> points;
  std::vector<Face> faces;
};

// The centroid of face f.
Vec3 centroid(const Mesh& m, const Face& f);

// Directed edge (from, to) -> face that contains it.
using HalfedgeMap = std::map<std::pair<int, int>, int>;

HalfedgeMap halfedges(const Mesh& m);

// Whether no face of h runs along the edge the other way (to, from).
bool isBoundary(const HalfedgeMap& h, int from, int to);

// Connected components of faces (two faces are connected when they share an edge).
// Only faces with use[f] take part; returns a component id per face (-1 if unused).
std::vector<int> faceComponents(const Mesh& m, const std::vector<bool>& use);

// Keeps the faces with keep[f], drops vertices no face uses, and renumbers.
Mesh subMesh(const Mesh& m, const std::vector<bool>& keep);

// Reads the vertices and triangles of an OBJ file; throws on anything else in a face line.
Mesh readObj(const std::string& path);
// Writes the mesh with `comment` in its first line (9 significant digits).
void writeObj(const std::string& path, const Mesh& m, const std::string& comment);

}  // namespace make_assets
