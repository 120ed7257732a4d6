// Ends a loop that provably never ends, after its second pass (docs/limits.md "Endless loops",
// alarm 99007).
//
// Why this is a proof and not a guess: the interpreter is deterministic, and which blocks run
// (the control flow) depends only on the values of variables, never on positions, modal G codes
// or the tool — unless an expression reads a system variable ($AA_IW, $P_EP, $AC_TIME, ...).
// So when a jump goes back to the same place twice, and between the two nothing was assigned,
// nothing was called, no frame was changed additively and no expression read a system
// variable or called a function other than the arithmetic ones, the second pass found every
// variable as the first one did and took every branch the same way: each later pass does
// again what the last one did, for ever. It may move (a warm-up program, `G91 G1 X1` drifting),
// or not; either way the program never reaches its end.
//
// A loop whose pass changes a variable (a counter, even one that nothing reads) is not judged
// here: it is ended by --max-blocks-without-motion or --max-blocks.
#pragma once

#include <cstddef>

#include "lang/block.hpp"

namespace ncoffset::interp {

class LoopWatch {
 public:
  // Something happened that may make the next pass differ (an assignment, a call, a frame
  // change, a read of the control's state).
  void dirty() { clean_ = false; }
  // Same as dirty() unless the expression at `node` is pure: literals, R parameters, user
  // variables and the arithmetic functions only.
  void expression(const lang::Block& b, int node) {
    if (node >= 0 && clean_ && !pure(b, node)) clean_ = false;
  }
  // A jump back (to an earlier line of the same program level). True when the same jump was
  // taken last time, at the same level of the same program, and nothing in between was dirty.
  bool backEdge(const void* program, size_t depth, size_t from, size_t to) {
    const bool again =
        armed_ && clean_ && program == program_ && depth == depth_ && from == from_ && to == to_;
    program_ = program;
    depth_ = depth;
    from_ = from;
    to_ = to;
    armed_ = true;
    clean_ = true;
    return again;
  }
  // A new run (program or init file) starts.
  void reset() { armed_ = false; }

  static bool pure(const lang::Block& b, int node);

 private:
  const void* program_ = nullptr;
  size_t depth_ = 0, from_ = 0, to_ = 0;
  bool armed_ = false;
  bool clean_ = false;
};

}  // namespace ncoffset::interp
