// The hole list's rows: each hole's size, perimeter, an area estimate and its status, sorted by
// any column and filtered by status, so that hundreds of holes stay manageable. No GL.
#pragma once

#include <string>
#include <vector>

#include "session.h"

namespace holefill::viewer {

enum class HoleStatus { Open, Partial, Filled, Failed };
const char* to_string(HoleStatus status);

struct HoleRow {
  int id = -1;
  std::size_t edges = 0;
  double perimeter = 0.0;
  double area = 0.0;  // of the boundary polygon (length of its vector area): an estimate
  HoleStatus status = HoleStatus::Open;
  // The last stage run, "failed", "island of N" (filled with hole N), "closed by N" (N's patch
  // closed it), with "+k" when the patch also closed k other loops.
  std::string stage;
  bool intersecting = false;  // the patch intersects the mesh
  std::string failure;        // why it failed or cannot be filled with its islands, for the tooltip
  // What the panel offers against the failure, by its own controls' names (the core's message
  // names none): "keep cutting patches" for a patch refused for cutting the mesh, "Remove small
  // pieces" for a loop through one vertex too often. Empty when nothing helps.
  std::string remedy;
};

enum class HoleColumn { Id, Edges, Perimeter, Area, Status };

struct HoleView {
  HoleColumn column = HoleColumn::Id;
  bool descending = false;
  // Which rows show: all when every flag is off.
  bool only_open = false;
  bool only_filled = false;
  bool only_failed = false;
  bool only_intersecting = false;
  bool shows(const HoleRow& row) const;
};

// One row per hole of the session, in id order.
std::vector<HoleRow> hole_rows(const Session& session);

// The rows `view` shows, in its order (ties by id, so the order is stable).
std::vector<HoleRow> arrange(std::vector<HoleRow> rows, const HoleView& view);

// The area of the polygon through `points` (the length of its vector area).
double polygon_area(const std::vector<Point>& points);

}  // namespace holefill::viewer
