// Which holes `holefill fill` (and the Python module's fill) takes: the ids of --holes and the
// pairs of --bridge, as typed, checked against the holes the mesh has.
#pragma once

#include <vector>

#include "fill_arguments.h"
#include "holefill/holes.h"

namespace holefill::cli {

// Adds a.hole_ids and a.bridges ("A,B") to a.selection once each id is one of the mesh's
// `holes`; throws UsageError naming a.input and the first id the mesh lacks, or the --bridge
// that is not two different ids or that --max-boundary excludes.
void select_holes(FillArguments& a, const std::vector<Hole>& holes);

}  // namespace holefill::cli
