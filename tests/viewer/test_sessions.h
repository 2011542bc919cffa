// What the viewer's tests share: sessions on the bundled meshes, and mesh equality (a rebuilt or
// replayed mesh must be the very same mesh).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

#include "holefill/mesh.h"
#include "session.h"

namespace holefill::viewer {

// Same vertex positions (bit for bit) and the same faces, in the same order.
inline bool same_mesh(const Mesh& a, const Mesh& b) {
  if (a.n_vertices() != b.n_vertices() || a.n_faces() != b.n_faces()) return false;
  for (const auto v : a.vertices()) {
    if (a.point(v) != b.point(VertexHandle(v.idx()))) return false;
  }
  for (const auto f : a.faces()) {
    auto fa = a.cfv_iter(f);
    auto fb = b.cfv_iter(FaceHandle(f.idx()));
    for (int i = 0; i < 3; ++i, ++fa, ++fb) {
      if (fa->idx() != fb->idx()) return false;
    }
  }
  return true;
}

inline const std::filesystem::path kBunny =
    std::filesystem::path(HOLEFILL_TEST_ASSETS) / "bunny.obj";

inline Session bunny_session() {
  Session session;
  EXPECT_TRUE(session.open(kBunny)) << session.notice().text;
  return session;
}

}  // namespace holefill::viewer
