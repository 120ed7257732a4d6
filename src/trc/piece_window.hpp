// A ring buffer for the look-ahead window of radius compensation: elements are appended at the
// back, written from the front and omitted from the back. Slots are reused (with the capacity
// of their vectors), so a long program allocates nothing per block once the window has grown
// to its size (at most MD20240 + 2 elements).
#pragma once

#include <cstddef>
#include <vector>

namespace ncoffset::trc {

template <typename T>
class PieceWindow {
 public:
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](size_t i) { return slots_[(head_ + i) & mask_]; }
  const T& operator[](size_t i) const { return slots_[(head_ + i) & mask_]; }
  T& front() { return (*this)[0]; }
  T& back() { return (*this)[size_ - 1]; }
  // The slot before `slot` (an element of the window but the front): the slot's neighbour in
  // memory, or the last slot at a wrap, without the index arithmetic of operator[] (§48).
  T& before(T& slot) { return &slot == slots_.data() ? slots_[capacity_ - 1] : *(&slot - 1); }
  // Whether an element satisfies `pred`, asked in slot order (not in window order): a pointer
  // walk over the one or two runs of slots the window occupies, without the index arithmetic of
  // operator[] (the compensation asks it once a block, docs/performance.md §28).
  template <typename Pred>
  bool any(Pred pred) const {
    const T* const s = slots_.data();
    const size_t first = capacity_ - head_ < size_ ? capacity_ - head_ : size_;  // up to the end
    for (const T *p = s + head_, *e = p + first; p != e; ++p)
      if (pred(*p)) return true;
    for (const T *p = s, *e = s + (size_ - first); p != e; ++p)  // wrapped to the start
      if (pred(*p)) return true;
    return false;
  }
  // A slot at the back to fill (it may hold an old element: the caller assigns all of it).
  T& pushBack() {
    if (size_ == capacity_) grow();
    ++size_;
    return back();
  }
  void popFront() {
    head_ = (head_ + 1) & mask_;
    --size_;
  }
  // Keeps the first n elements.
  void truncate(size_t n) { size_ = n < size_ ? n : size_; }
  void clear() {
    size_ = 0;
    head_ = 0;
  }

 private:
  // The capacity stays a power of two, so an index is a mask, not a division. (Out of line and
  // cold, so that pushBack, once a block, is inlined.)
  [[gnu::noinline, gnu::cold]] void grow() {
    std::vector<T> bigger(slots_.empty() ? 8 : slots_.size() * 2);
    for (size_t i = 0; i < size_; ++i) bigger[i] = std::move((*this)[i]);
    slots_ = std::move(bigger);
    capacity_ = slots_.size();
    mask_ = capacity_ - 1;
    head_ = 0;
  }

  std::vector<T> slots_;
  // slots_.size() and slots_.size() - 1, kept: a Piece's size is no power of two, and
  // vector::size() would divide by it.
  size_t capacity_ = 0, mask_ = 0;
  size_t head_ = 0, size_ = 0;
};

}  // namespace ncoffset::trc
