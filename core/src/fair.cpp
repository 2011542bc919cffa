#include "holefill/fair.h"

namespace holefill {

FairResult fair_patch(Mesh&, const Patch&, const FairOptions&) {
  return {false, "fairing is not available yet"};
}

}  // namespace holefill
