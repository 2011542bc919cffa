#include "feature_tables.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "bench_text.h"

namespace holefill::features {
namespace {

using quality::format;

std::string clean_text(const FeatureQuality& q) {
  std::string text;
  if (!q.manifold) text += "not manifold ";
  if (!q.closed) text += "open ";
  if (q.intersections) text += std::to_string(q.intersections) + " intersecting ";
  return text.empty() ? "yes" : text;
}

std::vector<std::string> case_names(const std::vector<Row>& rows) {
  std::vector<std::string> names;
  for (const auto& row : rows) {
    if (names.empty() || names.back() != row.name) names.push_back(row.name);
  }
  return names;
}

const Row* find_row(const std::vector<Row>& rows, const std::string& name,
                    const std::string& recipe) {
  for (const auto& row : rows) {
    if (row.name == name && row.recipe == recipe) return &row;
  }
  return nullptr;
}

// Cover per case, and its sums over all cases and over the cases with a crease in the hole,
// with each sum's ratio to CGAL's.
void print_cover(const std::vector<Row>& rows, const std::vector<std::string>& recipes) {
  std::cout << "**Cover: distance from the cut-away surface to the fill, mean (max), % of the "
               "bounding-box diagonal**\n\n| case | hole edges |";
  for (const auto& r : recipes) std::cout << " " << r << " |";
  std::cout << "\n|---|---:|";
  for (std::size_t i = 0; i < recipes.size(); ++i) std::cout << "---:|";
  std::cout << "\n";
  std::map<std::string, double> sum_all, sum_crease;
  for (const auto& name : case_names(rows)) {
    const Row* first = find_row(rows, name, recipes.front());
    std::cout << "| " << name << " | " << (first ? std::to_string(first->hole_edges) : "") << " |";
    bool crease = false;
    for (const auto& r : recipes) {
      const Row* row = find_row(rows, name, r);
      crease = crease || (row && row->quality.crease_samples > 0);
    }
    for (const auto& r : recipes) {
      const Row* row = find_row(rows, name, r);
      if (!row) {
        std::cout << " |";
        continue;
      }
      const double mean = 100.0 * row->quality.cover_mean;
      sum_all[r] += mean;
      if (crease) sum_crease[r] += mean;
      std::cout << " " << format(mean, 3) << " (" << format(100.0 * row->quality.cover_max, 2)
                << ") |";
    }
    std::cout << "\n";
  }
  auto sums = [&](const std::string& label, std::map<std::string, double>& sum) {
    std::cout << "| **" << label << "** | |";
    for (const auto& r : recipes) std::cout << " **" << format(sum[r], 3) << "** |";
    std::cout << "\n";
    if (!sum.count("cgal") || !(sum["cgal"] > 0.0)) return;
    std::cout << "| " << label << " / CGAL's | |";
    for (const auto& r : recipes) std::cout << " " << format(sum[r] / sum["cgal"], 2) << "x |";
    std::cout << "\n";
  };
  sums("sum, all cases", sum_all);
  sums("sum, cases with a crease", sum_crease);
  std::cout << "\n";
}

// The true crease inside the hole: its distance to the fill and the fill's sharpest angle near
// it, beside the truth's angle.
void print_crease(const std::vector<Row>& rows, const std::vector<std::string>& recipes) {
  std::cout << "**The crease inside the hole: distance to the fill, mean % of the diagonal / the "
               "fill's sharpest dihedral near it, degrees (truth: its own dihedral)**\n\n| case |";
  for (const auto& r : recipes) std::cout << " " << r << " |";
  std::cout << "\n|---|";
  for (std::size_t i = 0; i < recipes.size(); ++i) std::cout << "---:|";
  std::cout << "\n";
  for (const auto& name : case_names(rows)) {
    const Row* any = find_row(rows, name, recipes.front());
    if (!any || any->quality.crease_samples == 0) continue;
    std::cout << "| " << name << " |";
    for (const auto& r : recipes) {
      const Row* row = find_row(rows, name, r);
      if (!row) {
        std::cout << " |";
        continue;
      }
      const FeatureQuality& q = row->quality;
      std::cout << " " << format(100.0 * q.crease_mean, 3) << " / " << format(q.crease_dihedral, 0)
                << " |";
    }
    std::cout << "\n";
  }
  std::cout << "\n";
}

void print_every_measure(const std::vector<Row>& rows) {
  std::cout << "**Every measure** (distances in % of the bounding-box diagonal)\n\n"
               "| case | what | recipe | new V / F | cover mean | cover max | fill→truth mean "
               "| fill→truth max | crease dist mean | crease dist max | crease ∠ ° (truth) "
               "| max dihedral ° | min∠ p5 ° | clean | notes |\n"
               "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
  for (const auto& row : rows) {
    const FeatureQuality& q = row.quality;
    std::cout << "| " << row.name << " | " << row.what << " | " << row.recipe << " | "
              << q.patch.new_vertices << " / " << q.patch.faces << " | "
              << format(100.0 * q.cover_mean, 3) << " | " << format(100.0 * q.cover_max, 3) << " | "
              << format(100.0 * q.patch.mean_distance, 3) << " | "
              << format(100.0 * q.patch.max_distance, 3) << " | "
              << format(100.0 * q.crease_mean, 3) << " | " << format(100.0 * q.crease_max, 3)
              << " | " << format(q.crease_dihedral, 1) << " (" << format(q.truth_dihedral, 1)
              << ") | " << format(q.patch.max_dihedral, 1) << " | "
              << format(q.patch.min_angle_p5, 1) << " | " << clean_text(q) << " | " << row.notes
              << " |\n";
  }
  std::cout << "\n";
}

}  // namespace

void print_tables(const std::vector<Row>& rows, const std::vector<std::string>& recipes) {
  std::vector<std::string> fills;
  for (const auto& r : recipes) {
    if (r != "truth") fills.push_back(r);
  }
  if (!fills.empty()) print_cover(rows, fills);
  print_crease(rows, recipes);
  print_every_measure(rows);
}

}  // namespace holefill::features
