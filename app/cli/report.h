// The JSON report of `holefill fill --report`: options, mesh counts and per-hole statistics.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "holefill/fill.h"

namespace holefill::cli {

struct ReportInput {
  std::string input_path;
  std::string output_path;
  const FillOptions* options = nullptr;
  std::size_t vertices_before = 0, faces_before = 0;
  std::size_t vertices_after = 0, faces_after = 0;
  std::size_t holes_before = 0, holes_after = 0;
  const std::vector<HoleFill>* fills = nullptr;
};

void write_json_report(const ReportInput& input, std::ostream& out);

}  // namespace holefill::cli
