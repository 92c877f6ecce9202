// Visiting only the cells of an integer box that a thin shape may meet. A sliver's box (a long
// triangle across voxels, lines or grid cells) is mostly empty; halving the box and dropping the
// halves the shape cannot reach visits about as many cells as the shape crosses.
#ifndef VHACD_SRC_RANGE_HALVING_H_
#define VHACD_SRC_RANGE_HALVING_H_

#include <cstdint>

namespace vhacd {
namespace internal {

// Calls leaf(lo, hi) for boxes of at most `leaf_cells` cells covering the cells of [lo, hi]
// (inclusive, D dimensions) that may meet the shape. A larger box is split along its longest side
// (the first on a tie), low half first, after may_meet(lo, hi) says it may meet the shape; a box
// it rejects is dropped whole. may_meet must be conservative (never reject a box holding a cell
// the leaf's own test would keep): the cells the leaves accept are then those of a walk over
// every cell, in another order.
template <int D, typename MayMeet, typename Leaf>
void ForEachLeafRange(const int lo[D], const int hi[D], int64_t leaf_cells, MayMeet may_meet,
                      Leaf leaf) {
  struct Range {
    int lo[D], hi[D];
  };
  Range stack[32 * D + 2];  // depth-first: one entry per halving level, plus one
  int top = 0;
  for (int a = 0; a < D; ++a) {
    if (hi[a] < lo[a]) return;
    stack[0].lo[a] = lo[a];
    stack[0].hi[a] = hi[a];
  }
  top = 1;
  while (top > 0) {
    const Range r = stack[--top];
    int64_t cells = 1;
    int axis = 0;
    for (int a = 0; a < D; ++a) {
      cells *= r.hi[a] - r.lo[a] + 1;
      if (r.hi[a] - r.lo[a] > r.hi[axis] - r.lo[axis]) axis = a;
    }
    if (cells <= leaf_cells) {
      leaf(r.lo, r.hi);
      continue;
    }
    if (!may_meet(r.lo, r.hi)) continue;
    Range low = r, high = r;
    low.hi[axis] = r.lo[axis] + (r.hi[axis] - r.lo[axis] + 1) / 2 - 1;
    high.lo[axis] = low.hi[axis] + 1;
    stack[top++] = high;
    stack[top++] = low;
  }
}

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_RANGE_HALVING_H_
