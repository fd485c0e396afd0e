#pragma once
/// @file simd.hpp
/// @brief LUCENT_VECTOR_CLONES: compile a hot kernel twice, for x86-64-v3 (AVX2 + FMA) and for the
/// baseline, and pick one at load time (GCC's target_clones). Portable binaries, full-width
/// vectors. Not under ThreadSanitizer: the clone's resolver runs at load time, before TSan is
/// initialised, and crashes in its instrumentation.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(__SANITIZE_THREAD__)
#define LUCENT_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define LUCENT_VECTOR_CLONES
#endif
