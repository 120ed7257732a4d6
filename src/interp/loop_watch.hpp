// Ends a loop that provably never ends, after its second pass (docs/limits.md "Endless loops",
// alarm 99007).
//
// Why this is a proof and not a guess: the interpreter is deterministic, and which blocks run
// (the control flow) depends only on the values of variables, never on positions, modal G codes
// or the tool — unless an expression reads a system variable ($AA_IW, $P_EP, $AC_TIME, ...).
// So when a jump goes back to the same place twice, and between the two nothing was called, no
// frame was changed additively, no expression read a system variable or called a function other
// than the arithmetic ones, and no variable was assigned that an expression deciding the way
// (a condition, a CASE selector, a jump target, a computed M word) read in that pass, then every
// variable such an expression reads had the same value throughout the pass and has it still: the
// next pass takes every branch the same way, assigns the same variables, and so on for ever. A
// counter that only feeds positions (`R1=R1+1`, `G1 X=R1`) changes nothing that decides the way.
// The loop may move (a warm-up program, `G91 G1 X1` drifting) or not; either way the program
// never reaches its end.
//
// A pass that assigns a variable a deciding expression reads (a loop counter) is not judged here:
// such a loop is ended by --max-blocks-without-motion or --max-blocks.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

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
  // An expression that decides which block runs next (a condition, a CASE selector or value, a
  // jump target, a computed M word): it must be pure, and the variables it reads are remembered.
  void decides(const lang::Block& b, int node);
  // An assignment: its right-hand side must be pure, and its target must be a variable that no
  // deciding expression of this pass reads.
  void assignment(const lang::Block& b, const lang::Stmt& st);
  // A jump back (to an earlier line of the same program level). True when the same jump was
  // taken last time, at the same level of the same program, and nothing in between was dirty.
  bool backEdge(const void* program, size_t depth, size_t from, size_t to) {
    const bool again = armed_ && clean_ && program == program_ && depth == depth_ &&
                       from == from_ && to == to_ && !assignedIsRead();
    program_ = program;
    depth_ = depth;
    from_ = from;
    to_ = to;
    armed_ = true;
    clean_ = true;
    reads_.clear();
    assigned_.clear();
    return again;
  }
  // A new run (program or init file) starts.
  void reset() { armed_ = false; }

  static bool pure(const lang::Block& b, int node);

 private:
  // A variable as a key: an R parameter by its number, any R parameter (R[expr]), or a user
  // variable or array by the hash of its name. Two names with one hash only make the proof
  // give up where it need not: never a wrong "endless".
  using Key = std::uint64_t;
  // A small set of keys; a pass with more than it holds is not judged.
  struct KeySet {
    static constexpr size_t kCapacity = 64;
    std::array<Key, kCapacity> keys{};
    size_t size = 0;
    void clear() { size = 0; }
    bool add(Key k);  // false when full
  };
  void reads(const lang::Block& b, int node);
  static bool sameVariable(Key a, Key b);
  bool isRead(Key k) const;
  bool assignedIsRead() const;

  KeySet reads_, assigned_;
  const void* program_ = nullptr;
  size_t depth_ = 0, from_ = 0, to_ = 0;
  bool armed_ = false;
  bool clean_ = false;
};

}  // namespace ncoffset::interp
