#include "hole_table.h"

#include <algorithm>
#include <tuple>

namespace holefill::viewer {

const char* to_string(HoleStatus status) {
  switch (status) {
    case HoleStatus::Open:
      return "open";
    case HoleStatus::Partial:
      return "partial";
    case HoleStatus::Filled:
      return "filled";
    case HoleStatus::Failed:
      return "failed";
  }
  return "";
}

bool HoleView::shows(const HoleRow& row) const {
  const bool any = only_open || only_filled || only_failed || only_intersecting;
  if (!any) return true;
  return (only_open && row.status == HoleStatus::Open) ||
         (only_filled && row.status == HoleStatus::Filled) ||
         (only_failed && row.status == HoleStatus::Failed) ||
         (only_intersecting && row.intersecting);
}

double polygon_area(const std::vector<Point>& points) {
  Point twice_area(0.0, 0.0, 0.0);
  for (std::size_t i = 0; i < points.size(); ++i)
    twice_area += points[i] % points[(i + 1) % points.size()];
  return 0.5 * twice_area.norm();
}

std::vector<HoleRow> hole_rows(const Session& session) {
  std::vector<HoleRow> rows;
  for (const auto& hole : session.holes()) {
    // A loop another patch closed takes that patch's state.
    const int closer = session.closed_by(hole.id);
    const HoleFill& fill = session.fill(closer >= 0 ? closer : hole.id);
    std::vector<Point> points;
    for (const auto v : hole.vertices) points.push_back(session.mesh().point(v));
    HoleRow row;
    row.id = hole.id;
    row.edges = hole.size();
    row.perimeter = hole.perimeter;
    row.area = polygon_area(points);
    row.status = fill.failed()                     ? HoleStatus::Failed
                 : fill.stage() == Stage::Smoothed ? HoleStatus::Filled
                 : fill.stage() == Stage::Original ? HoleStatus::Open
                                                   : HoleStatus::Partial;
    row.stage = fill.failed() ? "failed" : to_string(fill.stage());
    const int outer = session.islands().outer[hole.id];
    if (closer >= 0) {
      row.stage = "closed by " + std::to_string(closer);
    } else if (outer >= 0 && fill.stage() == Stage::Original && !fill.failed()) {
      row.stage = "island of " + std::to_string(outer);
    } else if (!fill.joined_holes.empty() && fill.stage() != Stage::Original) {
      row.stage += " +" + std::to_string(fill.joined_holes.size());
    }
    row.intersecting = fill.self_intersections > 0;
    row.failure = fill.failed() ? fill.failure.message : session.islands().note[hole.id];
    if (fill.refused_intersections > 0) {
      row.remedy = "\"keep cutting patches\" keeps it";
    } else if (fill.failure.kind == FailureKind::VertexPassedTooOften) {
      row.remedy = "\"Remove small pieces\" removes the pieces that meet there";
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<HoleRow> arrange(std::vector<HoleRow> rows, const HoleView& view) {
  std::erase_if(rows, [&](const HoleRow& row) { return !view.shows(row); });
  const auto key = [&](const HoleRow& row) {
    switch (view.column) {
      case HoleColumn::Edges:
        return static_cast<double>(row.edges);
      case HoleColumn::Perimeter:
        return row.perimeter;
      case HoleColumn::Area:
        return row.area;
      case HoleColumn::Status:
        return static_cast<double>(row.status);
      case HoleColumn::Id:
        break;
    }
    return static_cast<double>(row.id);
  };
  std::stable_sort(rows.begin(), rows.end(), [&](const HoleRow& a, const HoleRow& b) {
    const double ka = key(a), kb = key(b);
    if (ka != kb) return view.descending ? ka > kb : ka < kb;
    return a.id < b.id;
  });
  return rows;
}

}  // namespace holefill::viewer
