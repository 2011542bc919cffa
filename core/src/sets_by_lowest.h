// Sets of elements joined pair by pair (faces across edges, vertices along edges), numbered in the
// order of their lowest elements: a union-find in which every element's parent is at most the
// element itself, so one pass in element order turns parents into set numbers. Four bytes an
// element and reads in the order the pairs come, where a walk from element to element waits on a
// cache miss at each step of a big mesh.
#pragma once

#include <algorithm>
#include <vector>

namespace holefill::detail {

// `label` holds, per element, the element's own index, or -1 for an element to leave out (never
// in a pair). for_each_pair(join) calls join(a, b) for each pair of elements to put in one set.
// Afterwards label[i] is the number of i's set (0 for the set holding element 0, and so on), -1
// left as it was. Returns the number of sets.
template <class ForEachPair>
int number_sets_by_lowest(std::vector<int>& label, ForEachPair&& for_each_pair) {
  std::vector<int>& parent = label;
  auto root = [&parent](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for_each_pair([&](int a, int b) {
    const int ra = root(a), rb = root(b);
    parent[std::max(ra, rb)] = std::min(ra, rb);
  });
  int sets = 0;
  for (int i = 0; i < static_cast<int>(parent.size()); ++i) {
    if (parent[i] < 0) continue;
    // parent[i] < i was turned into its set's number already.
    parent[i] = parent[i] == i ? sets++ : parent[parent[i]];
  }
  return sets;
}

}  // namespace holefill::detail
