#pragma once
/// @file simd.hpp
/// @brief LUCENT_VECTOR_CLONES: compile a hot kernel three times, for x86-64-v4 (AVX-512), x86-64-v3
/// (AVX2 + FMA) and the baseline, and pick one at load time (GCC's target_clones). Portable
/// binaries, full-width vectors. The v4 clone (masked gathers, 32 vector registers) took the Rd
/// sum from 4.8 to 2.6 ns per evaluation on a Zen 5 core (build/bench/rd_kernel_bench). Not under
/// ThreadSanitizer: the clone's resolver runs at load time, before TSan is initialised, and
/// crashes in its instrumentation.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(__SANITIZE_THREAD__)
#define LUCENT_VECTOR_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define LUCENT_VECTOR_CLONES
#endif

/// LUCENT_ALWAYS_INLINE: a kernel's inner functions, inlined into each clone whatever the inliner's
/// budget in the including file says: a call left in the loop stops its vectorisation (measured:
/// the Rd sum went from 4.4 to 30 ns per evaluation when an unrelated header change tipped the
/// budget).
#if defined(__GNUC__)
#define LUCENT_ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define LUCENT_ALWAYS_INLINE inline
#endif
