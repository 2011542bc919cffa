// holefill-make-big-mesh: a closed, gently wavy torus of about FACES triangles with HOLES small
// square holes spread over it, written as a binary little-endian PLY (float coordinates, as
// scanners write) or, for a .obj name, as an OBJ: the big meshes of bench/NOTEBOOK.md, generated
// rather than stored.
//
//   holefill-make-big-mesh FACES HOLES OUT.(ply|obj)
//   holefill-make-big-mesh 1400000 4 big.ply        # ~1.4M faces, four holes
//   holefill-make-big-mesh 10000000 1000 huge.ply   # ~10M faces, 1,000 holes
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

namespace {

struct Torus {
  int around = 0, across = 0;  // vertices along the big circle and the small one
  int vertex(int i, int j) const { return (i % around) * across + j % across; }
};

// Each hole removes a side x side block of cells (2 side^2 triangles, 4 side boundary edges);
// the sides cycle through 2..5 and the holes lie on a regular lattice, apart from each other.
std::vector<char> removed_cells(const Torus& torus, int holes) {
  std::vector<char> removed(static_cast<std::size_t>(torus.around) * torus.across, 0);
  const int rows = std::max(1, static_cast<int>(std::sqrt(holes * 2.0)));
  const int columns = (holes + rows - 1) / rows;
  for (int h = 0; h < holes; ++h) {
    const int side = 2 + h % 4;
    const int i0 = (h / columns) * torus.around / rows + 1;
    const int j0 = (h % columns) * torus.across / columns + 1;
    for (int i = i0; i < i0 + side; ++i) {
      for (int j = j0; j < j0 + side; ++j) {
        removed[static_cast<std::size_t>(i % torus.around) * torus.across + j % torus.across] = 1;
      }
    }
  }
  return removed;
}

void put_float(std::string& out, float value) {
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  out.append(raw, sizeof value);
}

void put_int(std::string& out, std::int32_t value) {
  char raw[sizeof value];
  std::memcpy(raw, &value, sizeof value);
  out.append(raw, sizeof value);
}

void put_text(std::string& out, auto value) {
  char text[32];
  out += ' ';
  out.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: holefill-make-big-mesh FACES HOLES OUT.(ply|obj)\n";
    return 2;
  }
  const double faces_wanted = std::atof(argv[1]);
  const int holes = std::atoi(argv[2]);
  const std::string path = argv[3];
  const bool obj = path.size() > 4 && path.substr(path.size() - 4) == ".obj";
  Torus torus;
  torus.across = std::max(8, static_cast<int>(std::sqrt(faces_wanted / 4.0)));
  torus.around = 2 * torus.across;
  const std::vector<char> removed = removed_cells(torus, holes);
  std::vector<std::int32_t> triangles;
  for (int i = 0; i < torus.around; ++i) {
    for (int j = 0; j < torus.across; ++j) {
      if (removed[static_cast<std::size_t>(i) * torus.across + j]) continue;
      const int a = torus.vertex(i, j), b = torus.vertex(i + 1, j), c = torus.vertex(i + 1, j + 1),
                d = torus.vertex(i, j + 1);
      triangles.insert(triangles.end(), {a, b, c, a, c, d});
    }
  }
  const int vertices = torus.around * torus.across;
  const std::size_t faces = triangles.size() / 3;
  std::string out;
  if (!obj) {
    out = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
          "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
          std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
  }
  for (int i = 0; i < torus.around; ++i) {
    const double u = 2 * std::numbers::pi * i / torus.around;
    for (int j = 0; j < torus.across; ++j) {
      const double v = 2 * std::numbers::pi * j / torus.across;
      const double r = 0.3 + 0.01 * std::sin(7 * u) * std::cos(5 * v);
      const float p[3] = {static_cast<float>((1 + r * std::cos(v)) * std::cos(u)),
                          static_cast<float>((1 + r * std::cos(v)) * std::sin(u)),
                          static_cast<float>(r * std::sin(v))};
      if (!obj) {
        for (const float x : p) put_float(out, x);
        continue;
      }
      out += 'v';
      for (const float x : p) put_text(out, x);
      out += '\n';
    }
  }
  for (std::size_t t = 0; t < faces; ++t) {
    if (!obj) out += static_cast<char>(3);
    if (obj) out += 'f';
    for (int c = 0; c < 3; ++c) {
      if (obj) {
        put_text(out, triangles[3 * t + c] + 1);
      } else {
        put_int(out, triangles[3 * t + c]);
      }
    }
    if (obj) out += '\n';
  }
  std::ofstream(path, std::ios::binary).write(out.data(), static_cast<std::streamsize>(out.size()));
  std::cout << path << ": " << vertices << " vertices, " << faces << " faces, " << holes
            << " holes\n";
  return 0;
}
