// Internal to tools/gltf: a linear-time check that parent/children links form a forest.
#ifndef HULLPACK_TOOLS_GLTF_NODE_FOREST_H_
#define HULLPACK_TOOLS_GLTF_NODE_FOREST_H_

#include <vector>

#include "scene/scene.h"

namespace hullpack {
namespace gltf_internal {

// Given nodes whose children indices are in range and whose `parent` fields agree with the children
// lists (so every node has at most one parent), returns the first node that no root reaches through
// children — one on or below a cycle — or -1 when the nodes form a forest. O(nodes), no recursion.
inline int FirstNodeOnCycle(const std::vector<Node>& nodes) {
  std::vector<bool> reached(nodes.size(), false);
  std::vector<int> stack;
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].parent == -1) stack.push_back(static_cast<int>(i));
  }
  while (!stack.empty()) {
    const int at = stack.back();
    stack.pop_back();
    if (reached[static_cast<size_t>(at)]) continue;
    reached[static_cast<size_t>(at)] = true;
    for (int c : nodes[static_cast<size_t>(at)].children) stack.push_back(c);
  }
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (!reached[i]) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace gltf_internal
}  // namespace hullpack

#endif  // HULLPACK_TOOLS_GLTF_NODE_FOREST_H_
