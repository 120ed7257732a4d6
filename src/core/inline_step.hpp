// NCOFFSET_INLINE_STEP marks a step of a per-block function that is a function of its own for
// reading but is inlined into its one caller (same file), as the single function it once was:
// such functions run for every block, and a call per step costs measurable instructions per
// block (docs/performance.md).
#pragma once

#define NCOFFSET_INLINE_STEP [[gnu::always_inline]] inline

// NCOFFSET_ONE_CALL marks a per-block function that forwards through a virtual call: GCC would
// speculate that the target is of the caller's own class and unroll the forwarding, testing the
// vtable at each level; the forward stays one call (docs/performance.md §38).
#if defined(__GNUC__) && !defined(__clang__)
#define NCOFFSET_ONE_CALL __attribute__((optimize("no-devirtualize-speculatively")))
#else
#define NCOFFSET_ONE_CALL
#endif
