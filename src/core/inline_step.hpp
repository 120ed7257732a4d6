// NCOFFSET_INLINE_STEP marks a step of a per-block function that is a function of its own for
// reading but is inlined into its one caller (same file), as the single function it once was:
// such functions run for every block, and a call per step costs measurable instructions per
// block (docs/performance.md).
#pragma once

#define NCOFFSET_INLINE_STEP [[gnu::always_inline]] inline
