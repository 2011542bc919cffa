// `holefill fill A B ... -o OUTDIR/` (or a folder as MESH): each mesh filled on its own with the
// same options, several at once (-j), into OUTDIR under its own name, exactly as `holefill fill
// A -o OUTDIR/A` would write it; a line per mesh and a total on stdout, one JSON report for the
// batch (--report), and the exit code of the worst mesh. A mesh that fails never stops the others.
#pragma once

#include "commands.h"

namespace holefill::cli {

// Whether `holefill fill` was given a batch: several meshes, or an -o that is a folder (an
// existing one, or a path ending in '/'; MESH may then be a folder of meshes).
bool is_batch(const FillArguments& arguments);

// Fills the batch; returns the most severe exit code of its meshes (kInternalError worst, then
// kOutOfMemory, kUsage, kBadInput, kWriteFailed, kSomeHolesNotFilled, kPatchesIntersect, kOk).
// Throws UsageError when the batch itself cannot be meant (standard input or output in it, two
// meshes of one name), FileError when the output folder cannot be made.
int run_batch(const FillArguments& arguments, const Streams& streams);

}  // namespace holefill::cli
