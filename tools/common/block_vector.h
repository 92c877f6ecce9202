// A growing array kept in blocks, for readers that append a large mesh element by element.
// Why: a std::vector that doubles holds its old and its new array at once while it moves (up to
// three times the data at the largest step), and leaves up to half of its last array unused. Here
// appending never moves what is stored; only the last block grows, and at most to kBlock elements.
// TakeAll moves the elements into one array of their size, freeing each block once copied, so the
// data is held at most once plus a block.
#ifndef HULLPACK_TOOLS_COMMON_BLOCK_VECTOR_H_
#define HULLPACK_TOOLS_COMMON_BLOCK_VECTOR_H_

#include <cstddef>
#include <vector>

namespace hullpack {

template <typename T>
class BlockVector {
 public:
  static constexpr int kShift = 18;
  static constexpr size_t kBlock = size_t{1} << kShift;  // elements of every block but the last

  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](size_t i) { return blocks_[i >> kShift][i & (kBlock - 1)]; }
  const T& operator[](size_t i) const { return blocks_[i >> kShift][i & (kBlock - 1)]; }

  void push_back(const T& value) {
    if (blocks_.empty() || blocks_.back().size() == kBlock) {
      blocks_.emplace_back();
      // The first block grows as a vector does (a small mesh stays small); a later one is only
      // started for a large array, so it is sized once.
      if (blocks_.size() > 1) blocks_.back().reserve(kBlock);
    }
    blocks_.back().push_back(value);
    ++size_;
  }

  // Calls f(element&) for every element, in order.
  template <typename F>
  void ForEach(F f) {
    for (std::vector<T>& block : blocks_) {
      for (T& value : block) f(value);
    }
  }

  // The elements in one array of their size; leaves this empty.
  std::vector<T> TakeAll() {
    std::vector<T> out;
    if (blocks_.size() == 1) {
      out.swap(blocks_[0]);
      out.shrink_to_fit();
    } else {
      out.reserve(size_);
      for (std::vector<T>& block : blocks_) {
        out.insert(out.end(), block.begin(), block.end());
        std::vector<T>().swap(block);
      }
    }
    blocks_.clear();
    size_ = 0;
    return out;
  }

 private:
  std::vector<std::vector<T>> blocks_;
  size_t size_ = 0;
};

}  // namespace hullpack

#endif  // HULLPACK_TOOLS_COMMON_BLOCK_VECTOR_H_
