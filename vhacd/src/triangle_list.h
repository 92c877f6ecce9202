// The triangles of a mesh: three vertex indices each, in one flat array that is either owned or
// the caller's own (a large input that needed no repair is then not copied; see ReadMesh).
#ifndef VHACD_SRC_TRIANGLE_LIST_H_
#define VHACD_SRC_TRIANGLE_LIST_H_

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace vhacd {
namespace internal {

class TriangleList {
 public:
  // One triangle's vertex indices: t[k] for k in 0..2, or a range-for over the three.
  class Ref {
   public:
    explicit Ref(const uint32_t* v) : v_(v) {}
    uint32_t operator[](int k) const { return v_[k]; }
    const uint32_t* begin() const { return v_; }
    const uint32_t* end() const { return v_ + 3; }
    std::array<uint32_t, 3> ToArray() const { return {v_[0], v_[1], v_[2]}; }

   private:
    const uint32_t* v_;
  };
  class Iterator {
   public:
    explicit Iterator(const uint32_t* v) : v_(v) {}
    Ref operator*() const { return Ref(v_); }
    Iterator& operator++() {
      v_ += 3;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return v_ != o.v_; }

   private:
    const uint32_t* v_;
  };

  TriangleList() = default;
  // The caller's `count` triangles at `indices` (3 each, contiguous), which must outlive the list.
  static TriangleList Borrow(const uint32_t* indices, size_t count) {
    TriangleList list;
    list.data_ = indices;
    list.count_ = count;
    return list;
  }
  // Copies and moves keep an owned list owned and a borrowed one borrowed.
  TriangleList(const TriangleList& o) { *this = o; }
  TriangleList& operator=(const TriangleList& o) {
    if (this == &o) return *this;
    owned_ = o.owned_;
    data_ = o.borrowed() ? o.data_ : owned_.data();
    count_ = o.count_;
    return *this;
  }
  TriangleList(TriangleList&& o) noexcept { *this = std::move(o); }
  TriangleList& operator=(TriangleList&& o) noexcept {
    if (this == &o) return *this;
    const bool borrowed = o.borrowed();
    owned_ = std::move(o.owned_);
    data_ = borrowed ? o.data_ : owned_.data();
    count_ = o.count_;
    o.owned_.clear();
    o.data_ = nullptr;
    o.count_ = 0;
    return *this;
  }

  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  bool borrowed() const { return data_ != nullptr && data_ != owned_.data(); }
  Ref operator[](size_t t) const { return Ref(data_ + 3 * t); }
  Iterator begin() const { return Iterator(data_); }
  Iterator end() const { return Iterator(data_ + 3 * count_); }

  // Growing an owned list (a borrowed one first becomes an owned copy).
  void reserve(size_t n) {
    Own();
    owned_.reserve(3 * n);
    data_ = owned_.data();
  }
  void push_back(const std::array<uint32_t, 3>& t) {
    Own();
    owned_.insert(owned_.end(), t.begin(), t.end());
    data_ = owned_.data();
    ++count_;
  }
  void push_back(Ref t) { push_back(t.ToArray()); }  // copied first: t may be in this list
  bool operator==(const TriangleList& o) const {
    return count_ == o.count_ && std::equal(data_, data_ + 3 * count_, o.data_);
  }
  std::vector<std::array<uint32_t, 3>> ToArrays() const {
    std::vector<std::array<uint32_t, 3>> out(count_);
    for (size_t t = 0; t < count_; ++t) out[t] = (*this)[t].ToArray();
    return out;
  }

 private:
  void Own() {
    if (borrowed()) owned_.assign(data_, data_ + 3 * count_);
  }
  std::vector<uint32_t> owned_;
  const uint32_t* data_ = nullptr;
  size_t count_ = 0;
};

}  // namespace internal
}  // namespace vhacd

#endif  // VHACD_SRC_TRIANGLE_LIST_H_
