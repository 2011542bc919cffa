// The JSON `holefill` writes: the report of `fill --report` (options, mesh counts, per-hole
// statistics) and `info --json`. Text that is not UTF-8 (a file name in another encoding) has
// each invalid byte replaced by U+FFFD, so the document is always valid JSON.
#pragma once

#include <string>
#include <vector>

#include "holefill/fill.h"
#include "preparation.h"

namespace holefill::cli {

struct ReportInput {
  std::string input_path;
  std::string output_path;
  const FillOptions* options = nullptr;
  const PreparedMesh* prepared = nullptr;  // stitching, pieces, what each loop is
  std::size_t vertices_before = 0, faces_before = 0;
  std::size_t vertices_after = 0, faces_after = 0;
  std::size_t holes_before = 0, holes_after = 0;
  const std::vector<HoleFill>* fills = nullptr;
};

// The report as a JSON document (ending in a newline).
std::string json_report(const ReportInput& input);

// What `holefill info --json` prints for `mesh` (read from `input_path`) and its loops, with the
// sharp features entering each hole under `features`.
std::string json_info(const std::string& input_path, const Mesh& mesh, const PreparedMesh& prepared,
                      const FeatureOptions& features = {});

// One line on the features entering a hole: "features: crease", "features: 3 lines, corner",
// "features: 1 line, not continued"; empty when none enter.
std::string features_summary(const HoleFeatures& features);

}  // namespace holefill::cli
