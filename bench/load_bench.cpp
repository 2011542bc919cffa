// Loading a 1M-face mesh: a 708 x 708 height field (999,698 triangles) as a plain
// OBJ, a textured OBJ (vt, vn and a material per corner and face), an OFF and a binary PLY,
// generated here in memory, each read by load_mesh_from_memory (parse, repairs, mesh). Coordinates
// are written as the shortest text of a float, as exporters do.
#include <benchmark/benchmark.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "holefill/io.h"

namespace holefill::bench {
namespace {

constexpr int kSide = 708;  // vertices per side: 2 * 707 * 707 = 999,698 triangles

void append_float(std::string& out, double value) {
  char text[32];
  out += ' ';
  out.append(text, std::to_chars(text, text + sizeof text, static_cast<float>(value)).ptr);
}

double height(int i, int j) { return 0.1 * std::sin(0.05 * i) * std::cos(0.07 * j); }

// The two triangles of each grid cell, by vertex index from 0.
template <class Emit>
void for_each_triangle(Emit&& emit) {
  for (int i = 0; i + 1 < kSide; ++i) {
    for (int j = 0; j + 1 < kSide; ++j) {
      const int a = i * kSide + j, b = a + 1, c = a + kSide, d = c + 1;
      emit(a, b, d);
      emit(a, d, c);
    }
  }
}

std::string grid_obj(bool textured) {
  std::string out = textured ? "mtllib grid.mtl\n" : "";
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      out += 'v';
      append_float(out, i / double(kSide));
      append_float(out, j / double(kSide));
      append_float(out, height(i, j));
      out += '\n';
      if (!textured) continue;
      out += "vt";
      append_float(out, i / double(kSide - 1));
      append_float(out, j / double(kSide - 1));
      out += "\nvn";
      append_float(out, -0.1 * std::cos(0.05 * i) * 0.05 * std::cos(0.07 * j));
      append_float(out, 0.1 * std::sin(0.05 * i) * 0.07 * std::sin(0.07 * j));
      append_float(out, 1.0);
      out += '\n';
    }
  }
  if (textured) out += "g grid\nusemtl ground\n";
  for_each_triangle([&](int a, int b, int c) {
    out += 'f';
    for (const int v : {a, b, c}) {
      const std::string index = std::to_string(v + 1);
      out += ' ';
      out += index;
      if (!textured) continue;
      for (int k = 0; k < 2; ++k) {
        out += '/';
        out += index;
      }
    }
    out += '\n';
  });
  return out;
}

// "x y z" lines, then "3 a b c" lines (indices from 0): the body of an OFF and of an ASCII PLY.
void append_vertex_and_face_lines(std::string& out) {
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      append_float(out, i / double(kSide));
      append_float(out, j / double(kSide));
      append_float(out, height(i, j));
      out += '\n';
    }
  }
  for_each_triangle([&](int a, int b, int c) {
    out += '3';
    for (const int v : {a, b, c}) {
      out += ' ';
      out += std::to_string(v);
    }
    out += '\n';
  });
}

std::string grid_off() {
  std::string out = "OFF\n" + std::to_string(kSide * kSide) + " " +
                    std::to_string(2 * (kSide - 1) * (kSide - 1)) + " 0\n";
  append_vertex_and_face_lines(out);
  return out;
}

std::string grid_ascii_ply() {
  std::string out = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(kSide * kSide) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(2 * (kSide - 1) * (kSide - 1)) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  append_vertex_and_face_lines(out);
  return out;
}

std::string grid_binary_ply() {
  const int faces = 2 * (kSide - 1) * (kSide - 1);
  std::string out =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(kSide * kSide) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
  auto put = [&out](auto value) {
    char raw[sizeof value];
    std::memcpy(raw, &value, sizeof value);
    out.append(raw, sizeof value);
  };
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      put(static_cast<float>(i / double(kSide)));
      put(static_cast<float>(j / double(kSide)));
      put(static_cast<float>(height(i, j)));
    }
  }
  for_each_triangle([&](int a, int b, int c) {
    put(std::uint8_t{3});
    for (const std::int32_t v : {a, b, c}) put(v);
  });
  return out;
}

void load(benchmark::State& state, const std::string& bytes, const char* name) {
  std::size_t faces = 0;
  for (auto _ : state) {
    const Mesh mesh = load_mesh_from_memory(bytes, name);
    faces = mesh.n_faces();
  }
  state.counters["faces"] = static_cast<double>(faces);
  state.counters["MB"] = static_cast<double>(bytes.size()) / 1e6;
}

void LoadObj1M(benchmark::State& state) {
  static const std::string bytes = grid_obj(false);
  load(state, bytes, "grid.obj");
}

void LoadTexturedObj1M(benchmark::State& state) {
  static const std::string bytes = grid_obj(true);
  load(state, bytes, "grid.obj");
}

void LoadOff1M(benchmark::State& state) {
  static const std::string bytes = grid_off();
  load(state, bytes, "grid.off");
}

void LoadAsciiPly1M(benchmark::State& state) {
  static const std::string bytes = grid_ascii_ply();
  load(state, bytes, "grid.ply");
}

void LoadBinaryPly1M(benchmark::State& state) {
  static const std::string bytes = grid_binary_ply();
  load(state, bytes, "grid.ply");
}

// CPU time of the whole process (a big OBJ is read on two threads), wall time beside it.
BENCHMARK(LoadObj1M)->Unit(benchmark::kMillisecond)->Iterations(3)->MeasureProcessCPUTime();
BENCHMARK(LoadTexturedObj1M)->Unit(benchmark::kMillisecond)->Iterations(3)->MeasureProcessCPUTime();
BENCHMARK(LoadOff1M)->Unit(benchmark::kMillisecond)->Iterations(3)->MeasureProcessCPUTime();
BENCHMARK(LoadAsciiPly1M)->Unit(benchmark::kMillisecond)->Iterations(3)->MeasureProcessCPUTime();
BENCHMARK(LoadBinaryPly1M)->Unit(benchmark::kMillisecond)->Iterations(3)->MeasureProcessCPUTime();

}  // namespace
}  // namespace holefill::bench
