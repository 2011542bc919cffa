// make_assets: writes the bundled test meshes of holefill (see assets/README.md).
//
//   holefill-make-assets <output-dir> <bunny_closed.obj>
//
// <bunny_closed.obj> is the Stanford bunny of the npm package `bunny`, converted by
// tools/bunny_to_obj.js. Everything else is generated here. The program is deterministic:
// no random numbers, every "noise" is a fixed sum of sines written out below.
//
// Each hole is cut the same way: remove the faces whose centroid lies inside a "wavy
// ball" (a ball whose radius varies with the angle around its axis), keep the
// connected piece of removed faces that contains the face nearest to the centre, then
// clean up until the boundary is a simple loop (see cutHole). The result is checked
// (one component, 2-manifold, consistently oriented, no pinched boundary vertex, the
// expected boundary loop sizes) and the program fails if a check does not hold.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr double kPi = std::numbers::pi;

// ---------------------------------------------------------------------------------------
// Minimal geometry and mesh types.

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
Vec3 normalized(Vec3 a) { return (1.0 / norm(a)) * a; }

using Face = std::array<int, 3>;  // counter-clockwise seen from outside

struct Mesh {
  std::vector<Vec3> points;
  std::vector<Face> faces;
};

Vec3 centroid(const Mesh& m, const Face& f) {
  return (1.0 / 3.0) * (m.points[f[0]] + m.points[f[1]] + m.points[f[2]]);
}

// Directed edge (from, to) -> face that contains it.
using HalfedgeMap = std::map<std::pair<int, int>, int>;

HalfedgeMap halfedges(const Mesh& m) {
  HalfedgeMap h;
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
    for (int i = 0; i < 3; ++i) {
      auto key = std::pair{m.faces[f][i], m.faces[f][(i + 1) % 3]};
      if (!h.emplace(key, f).second) throw std::runtime_error("directed edge used twice");
    }
  }
  return h;
}

bool isBoundary(const HalfedgeMap& h, int from, int to) { return !h.contains({to, from}); }

// Connected components of faces (two faces are connected when they share an edge).
// Only faces with use[f] take part; returns a component id per face (-1 if unused).
std::vector<int> faceComponents(const Mesh& m, const std::vector<bool>& use) {
  HalfedgeMap h;
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
    if (!use[f]) continue;
    for (int i = 0; i < 3; ++i) h[{m.faces[f][i], m.faces[f][(i + 1) % 3]}] = f;
  }
  std::vector<int> comp(m.faces.size(), -1);
  int next = 0;
  for (int start = 0; start < static_cast<int>(m.faces.size()); ++start) {
    if (!use[start] || comp[start] >= 0) continue;
    std::vector<int> stack{start};
    comp[start] = next;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        auto it = h.find({m.faces[f][(i + 1) % 3], m.faces[f][i]});
        if (it != h.end() && comp[it->second] < 0) {
          comp[it->second] = next;
          stack.push_back(it->second);
        }
      }
    }
    ++next;
  }
  return comp;
}

// Keeps the faces with keep[f], drops vertices no face uses, and renumbers.
Mesh subMesh(const Mesh& m, const std::vector<bool>& keep) {
  Mesh out;
  std::vector<int> newIndex(m.points.size(), -1);
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
    if (!keep[f]) continue;
    Face nf{};
    for (int i = 0; i < 3; ++i) {
      int& v = newIndex[m.faces[f][i]];
      if (v < 0) {
        v = static_cast<int>(out.points.size());
        out.points.push_back(m.points[m.faces[f][i]]);
      }
      nf[i] = v;
    }
    out.faces.push_back(nf);
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Checks.

struct Topology {
  int components = 0;
  std::vector<int> loops;  // edge count of each boundary loop, largest first
};

// Throws unless the mesh is a single consistently oriented 2-manifold component whose
// boundary vertices each lie on exactly one boundary loop.
Topology analyze(const Mesh& m) {
  const HalfedgeMap h = halfedges(m);  // throws on a repeated directed edge
  std::vector<int> boundaryNext(m.points.size(), -1);
  std::vector<int> faceCount(m.points.size(), 0);
  for (const Face& f : m.faces) {
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) throw std::runtime_error("degenerate face");
    for (int v : f) ++faceCount[v];
  }
  for (const auto& [edge, face] : h) {
    if (!isBoundary(h, edge.first, edge.second)) continue;
    if (boundaryNext[edge.first] >= 0) throw std::runtime_error("pinched boundary vertex");
    boundaryNext[edge.first] = edge.second;
  }
  // Every vertex must see one fan of faces: walk around it across edges and make sure the
  // walk visits all of its faces.
  for (int v = 0; v < static_cast<int>(m.points.size()); ++v) {
    if (faceCount[v] == 0) throw std::runtime_error("unreferenced vertex");
    // Start from the boundary edge if there is one, so the walk covers the whole fan.
    int start = -1;
    if (boundaryNext[v] >= 0) {
      start = h.at({v, boundaryNext[v]});
    } else {
      for (int f = 0; f < static_cast<int>(m.faces.size()) && start < 0; ++f)
        if (std::ranges::find(m.faces[f], v) != m.faces[f].end()) start = f;
    }
    int visited = 0;
    int f = start;
    do {
      ++visited;
      const Face& face = m.faces[f];
      const int i = static_cast<int>(std::ranges::find(face, v) - face.begin());
      const int prev = face[(i + 2) % 3];  // edge (prev, v) in this face; next face has (v, prev)
      auto it = h.find({v, prev});
      f = (it == h.end()) ? -1 : it->second;
    } while (f >= 0 && f != start);
    if (visited != faceCount[v]) throw std::runtime_error("vertex with several fans of faces");
  }
  Topology t;
  const std::vector<int> comp = faceComponents(m, std::vector<bool>(m.faces.size(), true));
  t.components = m.faces.empty() ? 0 : 1 + *std::ranges::max_element(comp);
  std::vector<bool> seen(m.points.size(), false);
  for (int v = 0; v < static_cast<int>(m.points.size()); ++v) {
    if (boundaryNext[v] < 0 || seen[v]) continue;
    int length = 0;
    for (int w = v; !seen[w]; w = boundaryNext[w]) {
      seen[w] = true;
      ++length;
    }
    t.loops.push_back(length);
  }
  std::ranges::sort(t.loops, std::greater{});
  return t;
}

// ---------------------------------------------------------------------------------------
// Hole cutting.

// One term a*sin(k*theta + phase) of a wavy radius.
struct Wave {
  double amplitude;
  int frequency;
  double phase;
};

// A ball around `center` whose radius depends on the angle theta measured around `axis`:
// r(theta) = radius + sum of the waves. A point is inside when its distance to the centre
// is below r(theta) for its own theta.
struct WavyBall {
  Vec3 center;
  Vec3 axis;  // roughly the surface normal at the centre
  double radius;
  std::vector<Wave> waves;

  bool contains(Vec3 p) const {
    const Vec3 n = normalized(axis);
    // Any vector not parallel to n gives a tangent frame (t1, t2).
    const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 t1 = normalized(cross(n, helper));
    const Vec3 t2 = cross(n, t1);
    const Vec3 d = p - center;
    const double theta = std::atan2(dot(d, t2), dot(d, t1));
    double r = radius;
    for (const Wave& w : waves) r += w.amplitude * std::sin(w.frequency * theta + w.phase);
    return norm(d) < r;
  }
};

// Removes the faces inside `region` (only the connected piece that contains the face
// nearest to region.center), then repeats until nothing changes:
//  - remove faces with two or three edges on the new hole's boundary (ears and dangling
//    faces, which would make the loop touch itself);
//  - remove all faces around a vertex that has several boundary loops through it;
//  - keep only the largest connected component.
// Boundary edges that existed before the cut (e.g. the rim of an open patch) are left alone.
Mesh cutHole(const Mesh& mesh, const WavyBall& region) {
  const int nf = static_cast<int>(mesh.faces.size());
  int seed = 0;
  for (int f = 1; f < nf; ++f) {
    if (norm(centroid(mesh, mesh.faces[f]) - region.center) <
        norm(centroid(mesh, mesh.faces[seed]) - region.center))
      seed = f;
  }
  std::vector<bool> inside(nf);
  for (int f = 0; f < nf; ++f) inside[f] = region.contains(centroid(mesh, mesh.faces[f]));
  if (!inside[seed]) throw std::runtime_error("hole region does not contain its centre");
  const std::vector<int> piece = faceComponents(mesh, inside);

  const HalfedgeMap before = halfedges(mesh);
  std::vector<bool> keep(nf);
  for (int f = 0; f < nf; ++f) keep[f] = !(inside[f] && piece[f] == piece[seed]);

  for (bool changed = true; changed;) {
    changed = false;
    HalfedgeMap now;
    for (int f = 0; f < nf; ++f)
      if (keep[f])
        for (int i = 0; i < 3; ++i) now[{mesh.faces[f][i], mesh.faces[f][(i + 1) % 3]}] = f;
    auto newBoundary = [&](int a, int b) {
      return isBoundary(now, a, b) && !isBoundary(before, a, b);
    };
    std::vector<int> boundaryOut(mesh.points.size(), 0);
    for (const auto& [edge, face] : now)
      if (isBoundary(now, edge.first, edge.second)) ++boundaryOut[edge.first];
    std::vector<bool> drop(nf, false);
    for (int f = 0; f < nf; ++f) {
      if (!keep[f]) continue;
      const Face& t = mesh.faces[f];
      int count = 0;
      for (int i = 0; i < 3; ++i) count += newBoundary(t[i], t[(i + 1) % 3]) ? 1 : 0;
      if (count >= 2) drop[f] = true;
      for (int v : t)
        if (boundaryOut[v] > 1) drop[f] = true;
    }
    for (int f = 0; f < nf; ++f) {
      if (drop[f]) {
        keep[f] = false;
        changed = true;
      }
    }
    // Largest component only (drops islands left inside the hole).
    const std::vector<int> comp = faceComponents(mesh, keep);
    std::vector<int> size(nf, 0);
    for (int f = 0; f < nf; ++f)
      if (keep[f]) ++size[comp[f]];
    const int largest = static_cast<int>(std::ranges::max_element(size) - size.begin());
    for (int f = 0; f < nf; ++f) {
      if (keep[f] && comp[f] != largest) {
        keep[f] = false;
        changed = true;
      }
    }
  }
  return subMesh(mesh, keep);
}

// ---------------------------------------------------------------------------------------
// Surfaces.

// Geodesic sphere: each face of an icosahedron split into k*k triangles, projected onto
// the unit sphere. 10*k*k + 2 vertices, 20*k*k faces.
Mesh geodesicSphere(int k) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  const std::vector<Vec3> ico = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                 {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                 {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  const std::vector<Face> icoFaces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  Mesh m;
  // A point of the subdivision is sum(w_i * corner_i) / k with integer weights w_i summing to
  // k. The weights, keyed by corner index, name the point exactly, so points on shared edges
  // and corners are found again from the neighbouring face.
  std::map<std::vector<std::pair<int, int>>, int> index;
  auto point = [&](const Face& corners, int wa, int wb, int wc) {
    std::vector<std::pair<int, int>> key;
    for (auto [c, w] : {std::pair{corners[0], wa}, {corners[1], wb}, {corners[2], wc}})
      if (w > 0) key.emplace_back(c, w);
    std::ranges::sort(key);
    auto [it, fresh] = index.emplace(key, static_cast<int>(m.points.size()));
    if (fresh) {
      Vec3 p;
      for (auto [c, w] : key) p = p + static_cast<double>(w) * ico[c];
      m.points.push_back(normalized(p));
    }
    return it->second;
  };
  for (const Face& t : icoFaces) {
    // Row i runs from corner a (i = 0) to the edge bc (i = k); j steps along it towards c.
    auto at = [&](int i, int j) { return point(t, k - i, i - j, j); };
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j <= i; ++j) {
        m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        if (j < i) m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return m;
}

// The implicit heart (x^2 + 9/4 y^2 + z^2 - 1)^3 - x^2 z^3 - 9/80 y^2 z^3 = 0 (z up, y the
// thin front-back direction). Negative inside. It is star-shaped around the origin.
double heartFunction(Vec3 p) {
  const double s = p.x * p.x + 2.25 * p.y * p.y + p.z * p.z - 1;
  const double z3 = p.z * p.z * p.z;
  return s * s * s - p.x * p.x * z3 - 9.0 / 80.0 * p.y * p.y * z3;
}

// The point where the ray from the origin in direction d leaves the heart.
Vec3 projectOntoHeart(Vec3 d) {
  double inner = 0, outer = 0.01;
  while (heartFunction(outer * d) < 0) {
    inner = outer;
    outer += 0.01;
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = (inner + outer) / 2;
    (heartFunction(mid * d) < 0 ? inner : outer) = mid;
  }
  return ((inner + outer) / 2) * d;
}

// A torus around the z axis: major radius R, tube radius r, n x m quads split in two.
Mesh torus(double R, double r, int n, int m) {
  Mesh t;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      t.points.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                          r * std::sin(v)});
    }
  }
  auto id = [&](int i, int j) { return (i % n) * m + (j % m); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      t.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return t;
}

// A square height field patch over [-1,1]^2 with n x n cells, diagonals alternating.
Mesh terrain(int n) {
  Mesh t;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double x = -1 + 2.0 * j / n, y = -1 + 2.0 * i / n;
      const double z = 0.12 * std::sin(3 * x + 0.5) * std::cos(2 * y) +
                       0.05 * std::sin(5 * x + 4 * y) + 0.08 * std::exp(-4 * (x * x + y * y));
      t.points.push_back({x, y, z});
    }
  }
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = id(i, j), b = id(i, j + 1), c = id(i + 1, j + 1), d = id(i + 1, j);
      if ((i + j) % 2 == 0) {
        t.faces.push_back({a, b, c});
        t.faces.push_back({a, c, d});
      } else {
        t.faces.push_back({a, b, d});
        t.faces.push_back({b, c, d});
      }
    }
  }
  return t;
}

// ---------------------------------------------------------------------------------------
// OBJ input and output.

Mesh readObj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Mesh m;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Vec3 p;
      if (!(s >> p.x >> p.y >> p.z)) throw std::runtime_error(path + ": bad line: " + line);
      m.points.push_back(p);
    } else if (tag == "f") {
      Face f{};
      std::string extra;
      if (!(s >> f[0] >> f[1] >> f[2]) || (s >> extra))
        throw std::runtime_error(path + ": not a plain triangle: " + line);
      for (int& v : f) {
        if (v < 1 || v > static_cast<int>(m.points.size()))
          throw std::runtime_error(path + ": bad vertex index: " + line);
        --v;
      }
      m.faces.push_back(f);
    }
  }
  return m;
}

void writeObj(const std::string& path, const Mesh& m, const std::string& comment) {
  FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw std::runtime_error("cannot write " + path);
  std::fprintf(out, "# %s\n# written by tools/make_assets.cpp (holefill)\n", comment.c_str());
  for (const Vec3& p : m.points) std::fprintf(out, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
  for (const Face& f : m.faces) std::fprintf(out, "f %d %d %d\n", f[0] + 1, f[1] + 1, f[2] + 1);
  std::fclose(out);
}

// Sum of the signed volumes of the tetrahedra (o, a, b, c) over the faces (a, b, c). For a
// closed surface this is its enclosed volume whatever o is; with holes it is still positive
// when the faces point away from a point o on the inner side.
double coneVolume(const Mesh& m, Vec3 o) {
  double v = 0;
  for (const Face& f : m.faces)
    v += dot(m.points[f[0]] - o, cross(m.points[f[1]] - o, m.points[f[2]] - o)) / 6;
  return v;
}

// Checks the mesh, prints a summary line, and writes the file. Fails unless the faces point
// away from `inside` and each boundary loop size lies in its [min, max] range (largest
// loop first).
void save(const std::string& dir, const std::string& name, const Mesh& m, Vec3 inside,
          const std::vector<std::pair<int, int>>& loopRanges, const std::string& comment) {
  const Topology t = analyze(m);
  std::printf("%-16s V=%5zu F=%5zu components=%d loops=%zu:", name.c_str(), m.points.size(),
              m.faces.size(), t.components, t.loops.size());
  for (int l : t.loops) std::printf(" %d", l);
  std::printf("\n");
  if (coneVolume(m, inside) <= 0) throw std::runtime_error(name + ": faces point inwards");
  bool ok = t.components == 1 && t.loops.size() == loopRanges.size();
  for (size_t i = 0; ok && i < t.loops.size(); ++i)
    ok = loopRanges[i].first <= t.loops[i] && t.loops[i] <= loopRanges[i].second;
  if (!ok) throw std::runtime_error(name + ": boundary loops not as expected");
  writeObj(dir + "/" + name, m, comment);
}

// Distance from p to the nearest boundary vertex of m.
double distanceToBoundary(const Mesh& m, Vec3 p) {
  const HalfedgeMap h = halfedges(m);
  double d = INFINITY;
  for (const auto& [edge, face] : h)
    if (isBoundary(h, edge.first, edge.second)) d = std::min(d, norm(m.points[edge.first] - p));
  return d;
}

// The vertex of m nearest to p, and the average normal of the faces around it.
std::pair<Vec3, Vec3> surfacePoint(const Mesh& m, Vec3 p) {
  int best = 0;
  for (int v = 1; v < static_cast<int>(m.points.size()); ++v)
    if (norm(m.points[v] - p) < norm(m.points[best] - p)) best = v;
  Vec3 n;
  for (const Face& f : m.faces)
    if (std::ranges::find(f, best) != f.end())
      n = n + cross(m.points[f[1]] - m.points[f[0]], m.points[f[2]] - m.points[f[0]]);
  return {m.points[best], normalized(n)};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <output-dir> <bunny_closed.obj>\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  try {
    const Mesh closedBunny = readObj(argv[2]);
    const Vec3 origin{0, 0, 0};
    // Sphere: one large hole with a wavy, strongly non-convex rim (a star with long arms).
    {
      const Mesh sphere = geodesicSphere(16);
      const Vec3 c = normalized({0.3, -0.4, 0.87});
      const WavyBall region{
          c, c, 1.0, {{0.75, 8, 0.0}, {0.25, 3, 2.1}, {0.1, 13, 0.5}, {0.04, 29, 2.0}}};
      save(dir, "sphere.obj", cutHole(sphere, region), origin, {{380, 430}},
           "unit sphere (geodesic, frequency 16) with one large wavy hole");
    }
    // Heart: cut the hole on a sphere, then push every vertex out along its ray onto the
    // implicit heart surface.
    {
      const Mesh sphere = geodesicSphere(14);
      const Vec3 c = normalized({0.55, -0.8, 0.25});
      // The phase of the 12-arm wave puts both poles between two arms, so the hole stays
      // clear of the heart's singular points (0, 0, 1) and (0, 0, -1).
      const WavyBall region{c, c, 1.1, {{0.8, 12, 2.5}, {0.25, 3, 1.7}, {0.07, 23, 0.9}}};
      Mesh heart = cutHole(sphere, region);
      for (Vec3& p : heart.points) p = projectOntoHeart(p);
      for (Vec3 singular : {Vec3{0, 0, 1}, Vec3{0, 0, -1}})
        if (distanceToBoundary(heart, singular) < 0.1)
          throw std::runtime_error("heart.obj: the hole reaches a singular point");
      save(dir, "heart.obj", heart, origin, {{470, 520}},
           "implicit heart surface with one large wavy hole");
    }
    // Bunny: the closed npm bunny with three holes (back, left haunch on the +z side, chest).
    // The bunny is y-up and faces -x.
    {
      Mesh bunny = closedBunny;
      const auto [back, backN] = surfacePoint(bunny, {1.2, 6.5, 0.4});
      const auto [side, sideN] = surfacePoint(bunny, {2.5, 1.5, 3.0});
      const auto [chest, chestN] = surfacePoint(bunny, {-4.3, 3.0, 0.3});
      bunny = cutHole(bunny, {back, backN, 2.3, {{0.9, 9, 0.3}, {0.35, 14, 1.7}, {0.15, 4, 2.2}}});
      bunny = cutHole(bunny, {side, sideN, 1.4, {{0.45, 4, 0.8}, {0.2, 7, 2.5}}});
      bunny = cutHole(bunny, {chest, chestN, 1.3, {{0.4, 3, 1.1}, {0.15, 6, 0.2}}});
      save(dir, "bunny.obj", bunny, {0, 3, 0}, {{80, 150}, {15, 60}, {15, 60}},
           "Stanford bunny (npm package bunny 1.0.1, public domain) with three holes");
    }
    // Extras for tests: a bumpy open patch with a star-shaped hole (two loops: the outer
    // rim and the hole; faces point up), and a torus with one hole on the outside of the
    // ring and one on the inside.
    {
      const Mesh patch = terrain(24);
      const auto [c, n] = surfacePoint(patch, {0.1, -0.05, 0.0});
      const WavyBall region{c, n, 0.45, {{0.18, 5, 0.0}, {0.05, 11, 1.0}}};
      save(dir, "ragged_disk.obj", cutHole(patch, region), {0, 0, -10}, {{96, 96}, {50, 70}},
           "bumpy height-field patch over [-1,1]^2 with a star-shaped hole");
    }
    {
      Mesh ring = torus(1.0, 0.4, 48, 20);
      const auto [outer, outerN] = surfacePoint(ring, {1.4, 0.0, 0.0});
      const auto [inner, innerN] = surfacePoint(ring, {-0.6, 0.0, 0.0});
      ring = cutHole(ring, {outer, outerN, 0.6, {{0.2, 5, 0.5}, {0.07, 9, 2.0}}});
      ring = cutHole(ring, {inner, innerN, 0.35, {{0.1, 4, 1.0}}});
      save(dir, "torus.obj", ring, origin, {{25, 70}, {15, 50}},
           "torus (R=1, r=0.4) with two holes");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_assets: %s\n", e.what());
    return 1;
  }
  return 0;
}
