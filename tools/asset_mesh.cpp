#include "asset_mesh.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace make_assets {

Vec3 centroid(const Mesh& m, const Face& f) {
  return (1.0 / 3.0) * (m.points[f[0]] + m.points[f[1]] + m.points[f[2]]);
}

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

}  // namespace make_assets
