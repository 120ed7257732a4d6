// The look-ahead window's ring buffer (trc/piece_window.hpp): any() walks the slots by pointer
// (the fast path radius compensation asks once a block); it must answer as the loop over the
// window by index (operator[], its twin) for every state the window can be in: growing, wrapped
// around the end of its slots, popped, truncated, cleared.
#include "trc/piece_window.hpp"

#include <gtest/gtest.h>

#include <random>

namespace ncoffset::trc {
namespace {

struct Item {
  int value = 0;
};

bool anyByIndex(const PieceWindow<Item>& w, int wanted) {
  for (size_t i = 0; i < w.size(); ++i)
    if (w[i].value == wanted) return true;
  return false;
}

TEST(PieceWindow, AnyAsTheIndexLoop) {
  std::mt19937 rng(2212);
  PieceWindow<Item> w;
  EXPECT_FALSE(w.any([](const Item&) { return true; }));  // no slots at all
  int next = 0;
  for (int step = 0; step < 200000; ++step) {
    const int op = static_cast<int>(rng() % 10);
    if (op < 5 || w.empty()) {
      w.pushBack().value = ++next;
    } else if (op < 8) {
      w.popFront();
    } else if (op == 8) {
      w.truncate(rng() % (w.size() + 1));
    } else if (rng() % 50 == 0) {
      w.clear();
    }
    // Values in the window, just outside it (popped or truncated slots keep theirs), and never
    // written.
    for (int wanted : {next, next - 1, next - static_cast<int>(w.size()),
                       next - static_cast<int>(rng() % 40), next + 1}) {
      ASSERT_EQ(w.any([wanted](const Item& it) { return it.value == wanted; }),
                anyByIndex(w, wanted))
          << "step " << step << " size " << w.size() << " wanted " << wanted;
    }
  }
}

}  // namespace
}  // namespace ncoffset::trc
