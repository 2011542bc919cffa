#include "holefill/failure.h"

#include <ostream>

namespace holefill {

const char* to_string(FailureKind kind) {
  switch (kind) {
    case FailureKind::None:
      return "none";
    case FailureKind::TooFewEdges:
      return "too-few-edges";
    case FailureKind::TooManyEdges:
      return "too-many-edges";
    case FailureKind::VertexPassedTooOften:
      return "vertex-passed-too-often";
    case FailureKind::CoincidentPoints:
      return "coincident-points";
    case FailureKind::BackOfLoneTriangle:
      return "back-of-lone-triangle";
    case FailureKind::NoTriangulation:
      return "no-triangulation";
    case FailureKind::DegenerateTriangle:
      return "degenerate-triangle";
    case FailureKind::LeftPinched:
      return "left-pinched";
    case FailureKind::OutOfMemory:
      return "out-of-memory";
    case FailureKind::MeshRefusedTriangle:
      return "mesh-refused-triangle";
    case FailureKind::IntersectsMesh:
      return "intersects-mesh";
    case FailureKind::TooManyLoops:
      return "too-many-loops";
    case FailureKind::LoopsShareVertex:
      return "loops-share-vertex";
    case FailureKind::NoBridge:
      return "no-bridge";
    case FailureKind::BadBridge:
      return "bad-bridge";
    case FailureKind::Cancelled:
      return "cancelled";
  }
  return "unknown";
}

std::ostream& operator<<(std::ostream& out, const Failure& failure) {
  if (!failure.failed()) return out;
  return out << failure.message << " (" << to_string(failure.kind) << ")";
}

}  // namespace holefill
