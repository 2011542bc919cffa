// Why a hole, or a group of loops filled together, was not filled: a kind that a program tests and
// acts on, and a message that tells a person, with the numbers of this case. Every stage that can
// refuse a hole (planning its triangulation, joining loops, adding the patch, checking it against
// the mesh) says so with one of these.
#pragma once

#include <iosfwd>
#include <string>

namespace holefill {

enum class FailureKind {
  None,
  // The loop itself.
  TooFewEdges,   // fewer than 3 boundary edges
  TooManyEdges,  // more than the dynamic program takes (kMaxPolygonSize, kMaxFullSearchEdges)
  VertexPassedTooOften,  // through one vertex more than kMaxVertexPasses times
  CoincidentPoints,      // twice through one position: a zero-width crack or an unwelded seam
  BackOfLoneTriangle,    // the rim of a lone triangle: a patch would be a copy of it
  // Its triangulation.
  NoTriangulation,     // no valid triangulation among the ones searched
  DegenerateTriangle,  // the best one has a zero-area triangle
  LeftPinched,         // a pinched loop whose patch would leave the vertex pinched
  OutOfMemory,
  // Adding the patch to the mesh.
  MeshRefusedTriangle,  // a patch triangle would make a vertex or edge non-manifold
  IntersectsMesh,       // every patch tried cuts the mesh (do no harm)
  // Loops filled together (islands, bridges).
  TooManyLoops,      // more than kMostJoinedLoops
  LoopsShareVertex,  // loops to join touch, or one passes twice through a vertex
  NoBridge,          // no bridge gives a valid triangulation
  BadBridge,         // a requested bridge: one hole twice, a hole bridged twice or as an island,
                     // or holes too far apart
  Cancelled,         // the caller's Progress asked the work to stop (progress.h)
};

// The kind's name as reports write it: "none", "too-few-edges", ... (lower case, hyphens).
const char* to_string(FailureKind kind);

struct Failure {
  FailureKind kind = FailureKind::None;
  std::string message;  // what failed and why, for people; empty when kind is None

  bool failed() const { return kind != FailureKind::None; }
  bool operator==(const Failure&) const = default;
};

// Writes "MESSAGE (KIND)", e.g. for a test's diagnostics; nothing for no failure.
std::ostream& operator<<(std::ostream& out, const Failure& failure);

}  // namespace holefill
