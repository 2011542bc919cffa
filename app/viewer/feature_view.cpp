#include "feature_view.h"

#include "replay.h"

namespace holefill::viewer {
namespace {

glm::vec3 to_vec3(const Point& p) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

// Segments joining `points` in order.
void add_polyline(const std::vector<Point>& points, std::vector<BoundarySegment>& segments) {
  for (std::size_t i = 1; i < points.size(); ++i) {
    segments.push_back({to_vec3(points[i - 1]), to_vec3(points[i]), -1});
  }
}

// A junction's curves with their ends: a crease from the first line's entry to the second's; a
// corner from each line's entry to the corner point.
std::vector<std::vector<Point>> curves(const HoleFeatures& features,
                                       const FeatureJunction& junction) {
  const auto entry = [&](int line) { return features.lines.at(line).traced.front(); };
  std::vector<std::vector<Point>> result;
  for (std::size_t i = 0; i < junction.paths.size(); ++i) {
    std::vector<Point> curve{entry(junction.lines.at(i))};
    curve.insert(curve.end(), junction.paths[i].begin(), junction.paths[i].end());
    curve.push_back(junction.corner ? junction.corner_point : entry(junction.lines.at(1)));
    result.push_back(std::move(curve));
  }
  return result;
}

}  // namespace

const HoleFeatures& FeatureView::of(const Mesh& mesh, std::uint64_t mesh_version, const Hole* hole,
                                    const FeatureOptions& options) {
  const int hole_id = hole ? hole->id : -1;
  if (version_ != 0 && mesh_version == mesh_version_ && hole_id == hole_id_ &&
      options == options_) {
    return features_;
  }
  mesh_version_ = mesh_version;
  hole_id_ = hole_id;
  options_ = options;
  features_ = hole ? find_hole_features(mesh, *hole, options) : HoleFeatures{};
  version_ = next_serial();
  return features_;
}

std::string feature_summary(const HoleFeatures& features) {
  const std::size_t n = features.lines.size();
  if (n == 0) return {};
  std::string text = std::to_string(n) +
                     (n == 1 ? " sharp feature line enters" : " sharp feature lines enter") +
                     " the hole: ";
  if (!features.continued()) {
    return text + "not continued (" + (features.note.empty() ? "no junction" : features.note) +
           "), the paper's fill";
  }
  std::size_t creases = 0, corners = 0;
  for (const auto& junction : features.junctions) (junction.corner ? corners : creases) += 1;
  text += "continued";
  if (creases)
    text +=
        " as " + (creases == 1 ? std::string("a crease") : std::to_string(creases) + " creases");
  if (creases && corners) text += " and";
  if (corners)
    text +=
        " to " + (corners == 1 ? std::string("a corner") : std::to_string(corners) + " corners");
  return text;
}

std::vector<BoundarySegment> feature_segments(const HoleFeatures& features, bool continued) {
  std::vector<BoundarySegment> segments;
  if (!continued) {
    for (const auto& line : features.lines) add_polyline(line.traced, segments);
    return segments;
  }
  if (!features.continued()) return segments;
  for (const auto& junction : features.junctions) {
    for (const auto& curve : curves(features, junction)) add_polyline(curve, segments);
  }
  return segments;
}

}  // namespace holefill::viewer
