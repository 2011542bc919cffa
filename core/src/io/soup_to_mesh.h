// From the polygons a file describes to a Mesh: polygons are triangulated, faces flipped to agree
// with their neighbours, exact duplicates and faces using a vertex twice dropped, faces that would
// make an edge non-manifold kept on their own copies of their corners, and a vertex where closed
// surfaces touch split into one copy per surface. Every repair is counted in the LoadReport.
#pragma once

#include "holefill/io.h"
#include "soup.h"
#include "two_threads.h"

namespace holefill::io {

// The mesh the soup describes after the repairs above (report.format must be set: STL's welded
// positions are not counted as duplicates). The soup is taken so that its arrays can be freed as
// soon as they are used up, before the mesh's are made.
// Independent parts run on two threads from `two_threads_from` faces on (two_threads.h; the mesh is
// the same either way).
Mesh build_mesh(Soup soup, LoadReport& report, std::size_t two_threads_from = kTwoThreadsFrom);

// One sentence per kind of repair counted in `report`, appended to report.warnings.
void add_warnings(LoadReport& report);

}  // namespace holefill::io
