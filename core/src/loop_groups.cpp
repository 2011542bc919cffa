#include "holefill/loop_groups.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace holefill {
namespace {

double diameter(const Mesh& mesh, const Hole& hole) {
  double largest = 0.0;
  for (const auto a : hole.vertices) {
    for (const auto b : hole.vertices) {
      largest = std::max(largest, (mesh.point(a) - mesh.point(b)).sqrnorm());
    }
  }
  return std::sqrt(largest);
}

double gap(const Mesh& mesh, const Hole& a, const Hole& b) {
  double closest = INFINITY;
  for (const auto u : a.vertices) {
    for (const auto v : b.vertices) {
      closest = std::min(closest, (mesh.point(u) - mesh.point(v)).sqrnorm());
    }
  }
  return std::sqrt(closest);
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Why holes a and b cannot be bridged as asked (FailureKind::BadBridge), or no failure.
Failure bridge_problem(const Mesh& mesh, const std::vector<Hole>& holes, const IslandMap& islands,
                       std::pair<int, int> bridge, const std::vector<int>& bridged_with,
                       const JoinOptions& options) {
  const auto [a, b] = bridge;
  const std::string pair = "holes " + std::to_string(a) + " and " + std::to_string(b);
  auto bad = [](std::string message) {
    return Failure{FailureKind::BadBridge, std::move(message)};
  };
  if (a == b)
    return bad("a bridge needs two different holes, got hole " + std::to_string(a) + " twice");
  for (const int hole : {a, b}) {
    if (bridged_with[hole] >= 0) {
      return bad("hole " + std::to_string(hole) + " is bridged twice (to holes " +
                 std::to_string(bridged_with[hole]) + " and " + std::to_string(hole == a ? b : a) +
                 ")");
    }
    if (islands.outer[hole] >= 0 && islands.outer[hole] != (hole == a ? b : a)) {
      return bad("hole " + std::to_string(hole) + " is an island of hole " +
                 std::to_string(islands.outer[hole]) +
                 " and is filled with it; bridge them with island detection off");
    }
  }
  const double distance = gap(mesh, holes[a], holes[b]);
  const double size = std::max(diameter(mesh, holes[a]), diameter(mesh, holes[b]));
  if (distance > options.max_gap * size) {
    return bad(pair + " are too far apart to bridge: " + number(distance) +
               " between their closest vertices, more than " + number(options.max_gap) +
               " times the larger loop's diameter (" + number(size) + ")");
  }
  return {};
}

}  // namespace

std::size_t LoopGroup::boundary_edges(const std::vector<Hole>& all) const {
  std::size_t edges = 0;
  for (const int id : holes) edges += all[id].size();
  return edges;
}

std::vector<LoopGroup> group_loops(const Mesh& mesh, const std::vector<Hole>& holes,
                                   const IslandMap& islands,
                                   const std::vector<std::pair<int, int>>& bridges,
                                   const JoinOptions& options) {
  std::vector<int> group_of(holes.size(), -1), bridged_with(holes.size(), -1);
  std::vector<LoopGroup> groups;
  // Puts `hole` and its islands in groups[group].
  auto add_with_islands = [&](std::size_t group, int hole) {
    std::vector<int> members{hole};
    members.insert(members.end(), islands.islands[hole].begin(), islands.islands[hole].end());
    for (const int member : members) {
      if (group_of[member] == static_cast<int>(group)) continue;  // bridged to its own island
      groups[group].holes.push_back(member);
      group_of[member] = static_cast<int>(group);
    }
  };
  for (const auto& bridge : bridges) {
    const Failure problem = bridge_problem(mesh, holes, islands, bridge, bridged_with, options);
    if (problem.failed()) {
      // The pair stays open, each with what else it would have been filled with.
      for (const int hole : {bridge.first, bridge.second}) {
        if (group_of[hole] >= 0) {
          groups[group_of[hole]].problem = problem;
          continue;
        }
        groups.push_back({{}, problem, {}});
        add_with_islands(groups.size() - 1, islands.outer[hole] >= 0 ? islands.outer[hole] : hole);
      }
      continue;
    }
    bridged_with[bridge.first] = bridge.second;
    bridged_with[bridge.second] = bridge.first;
    groups.emplace_back();
    add_with_islands(groups.size() - 1, bridge.first);
    add_with_islands(groups.size() - 1, bridge.second);
  }
  for (const auto& hole : holes) {
    if (group_of[hole.id] >= 0 || islands.outer[hole.id] >= 0) continue;
    groups.emplace_back();
    add_with_islands(groups.size() - 1, hole.id);
  }
  for (auto& group : groups) {
    for (const int hole : group.holes) {
      if (group.note.empty()) group.note = islands.note[hole];
    }
  }
  return groups;
}

}  // namespace holefill
