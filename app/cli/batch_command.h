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

// The threads that read, prepare and fill each mesh of a batch filling `jobs` meshes at once:
// `threads` when given (--threads; then the batch may run jobs x threads), else the process's
// `cores` shared among the jobs, at least one each, so that a batch keeps about one thread per
// core instead of a fill's every core per mesh (jobs x cores). The outputs are the same whatever
// the split.
unsigned threads_per_mesh(unsigned threads, unsigned jobs, unsigned cores);

// Fills the batch (jobs: -j, else one per core, at most one per mesh); returns the most severe exit
// code of its meshes (kInternalError worst, then kOutOfMemory, kUsage, kBadInput, kWriteFailed,
// kSomeHolesNotFilled, kPatchesIntersect, kOk). Throws UsageError when the batch itself cannot be
// meant (standard input or output in it, two meshes of one name), FileError when the output folder
// cannot be made.
int run_batch(const FillArguments& arguments, const Streams& streams);

}  // namespace holefill::cli
