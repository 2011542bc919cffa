// What one fuzz input exercises, shared by the libFuzzer targets (fuzz_*.cpp) and by the
// regression test that replays the corpus and every crash found (tests/robust). Each returns
// the first broken promise in words, or an empty string when all held.
#pragma once

#include <string>

namespace holefill::fuzz {

// Reads `bytes` as a file named "input<extension>": either a FileError is thrown, or the mesh is
// oriented and edge-manifold with finite points; then its small holes are filled and the fill
// guarantees checked.
std::string load_input(const std::string& bytes, const std::string& extension);

// Builds a band of triangles around a polygon whose points (small integers, so that collinear
// and coincident points are common) and fill options come from `bytes`, fills both of its rims
// (one at a time, or stepped in turn) and checks the fill guarantees.
std::string fill_input(const std::string& bytes);

}  // namespace holefill::fuzz
