// Matching the feature lines that enter a hole into junctions (features.h), and routing the
// continued curves through the hole (internal).
#pragma once

#include "holefill/features.h"

namespace holefill::detail {

// Fills features.junctions from features.lines: first corners (three or more lines whose
// extensions meet near one point inside the hole, each pointing at it), then creases (pairs of
// the remaining lines pointing at each other along a straight or evenly curving path), each with
// its paths. When a line is left without a junction, or a junction's path is degenerate, the
// junctions are cleared and features.note says why.
void match_feature_lines(const Mesh& mesh, const Hole& hole, HoleFeatures& features);

}  // namespace holefill::detail
