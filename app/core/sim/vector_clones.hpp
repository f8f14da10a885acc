#pragma once

// GCC builds an AVX2 copy of each function so marked beside the baseline
// x86-64 (SSE2) one and picks per machine when the program loads, so one
// binary runs anywhere and uses 8-wide vectors where it can. Not "fma", nor
// "arch=x86-64-v3", which implies it: GCC would then contract a * b + c into
// fused multiply-adds, and the CPU results would stop matching the generic
// path, older runs and llvmpipe bit for bit. Used by the fused CPU kernels
// (cpu_kernels.cpp) and by the bench's probes, which must be built alike.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define MORPHOGEN_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MORPHOGEN_VECTOR_CLONES
#endif
