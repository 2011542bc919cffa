#include "hole_selection.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"

namespace holefill::cli {
namespace {

// "A,B": two different hole ids of the mesh, whose loops --max-boundary does not exclude.
std::pair<int, int> parse_bridge(const FillArguments& a, const std::string& text,
                                 const std::vector<Hole>& holes) {
  const std::size_t hole_count = holes.size();
  const std::size_t comma = text.find(',');
  std::vector<int> ids;
  for (const std::string& part :
       {text.substr(0, comma), comma == std::string::npos ? "" : text.substr(comma + 1)}) {
    if (part.empty() || part.size() > 9 ||
        !std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c); })) {
      throw UsageError("--bridge takes two hole ids, A,B (e.g. --bridge 0,3), got '" + text + "'");
    }
    const int id = std::stoi(part);
    if (id >= static_cast<int>(hole_count)) {
      throw UsageError("--bridge: " + a.input + " has no hole " + part + " (it has " +
                       std::to_string(hole_count) + ")");
    }
    ids.push_back(id);
  }
  if (ids[0] == ids[1]) {
    throw UsageError("--bridge joins two different holes, got hole " + std::to_string(ids[0]) +
                     " twice ('" + text + "')");
  }
  // The band's loops (without any islands, which only add edges) over the limit: the bridge
  // would be left out of the fill without a word.
  const std::size_t edges = holes[ids[0]].size() + holes[ids[1]].size();
  const std::size_t most = a.selection.max_boundary_edges;
  if (most && edges > most) {
    throw UsageError("--bridge " + text + ": holes " + std::to_string(ids[0]) + " and " +
                     std::to_string(ids[1]) + " have " + std::to_string(edges) +
                     " boundary edges together, more than --max-boundary " + std::to_string(most) +
                     " fills");
  }
  return {ids[0], ids[1]};
}

}  // namespace

void select_holes(FillArguments& a, const std::vector<Hole>& holes) {
  const std::size_t hole_count = holes.size();
  for (const std::int64_t id : a.hole_ids) {
    if (id >= static_cast<std::int64_t>(hole_count)) {
      throw UsageError("--holes: " + a.input + " has no hole " + std::to_string(id) + " (it has " +
                       std::to_string(hole_count) + ")");
    }
    a.selection.hole_ids.push_back(static_cast<int>(id));
  }
  for (const std::string& text : a.bridges) {
    a.selection.bridges.push_back(parse_bridge(a, text, holes));
  }
}

}  // namespace holefill::cli
