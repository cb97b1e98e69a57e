#pragma once
// MFWAVE_ALWAYS_INLINE: asks the compiler to inline a per-pair function into its pair loop (GCC
// and Clang otherwise may keep a large member such as pair_sweep::Sweep::row out of line, and the call with
// its arguments through memory then costs as much as the arithmetic).

// MFWAVE_INLINE_LAMBDA: the same for a lambda handed to a pair loop (pair_sweep::forEachRowInBlocks),
// written after its parameter list.

#if defined(__GNUC__) || defined(__clang__)
#define MFWAVE_ALWAYS_INLINE inline __attribute__((always_inline))
#define MFWAVE_INLINE_LAMBDA __attribute__((always_inline))
#else
#define MFWAVE_ALWAYS_INLINE inline
#define MFWAVE_INLINE_LAMBDA
#endif
