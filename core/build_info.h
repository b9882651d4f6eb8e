// What a translation unit was compiled with that decides its binary interface:
// the compiler, the processor's vector extensions it may use (-march=native)
// and Eigen's alignment of fixed-size matrices (EIGEN_MAX_ALIGN_BYTES, which
// follows the vector width). Code built with one signature must not be linked
// or loaded with code built with another (an Eigen::Vector4d aligned to 16
// bytes in one and 32 in the other is undefined behaviour; AVX-512 code on a
// processor without it stops with SIGILL). The Python module compares its own
// signature with the libraries' when it is imported (python/framedyn_module.cpp).
#pragma once

#include <Eigen/Core>

#define FRAMEDYN_STR_DETAIL(x) #x
#define FRAMEDYN_STR(x) FRAMEDYN_STR_DETAIL(x)

#if defined(__clang__)
#define FRAMEDYN_BUILD_COMPILER "clang " __clang_version__
#elif defined(__GNUC__)
#define FRAMEDYN_BUILD_COMPILER "gcc " __VERSION__
#else
#define FRAMEDYN_BUILD_COMPILER "unknown compiler"
#endif

#if defined(__AVX512F__)
#define FRAMEDYN_BUILD_VECTOR "avx512f"
#elif defined(__AVX2__)
#define FRAMEDYN_BUILD_VECTOR "avx2"
#elif defined(__AVX__)
#define FRAMEDYN_BUILD_VECTOR "avx"
#elif defined(__SSE4_2__)
#define FRAMEDYN_BUILD_VECTOR "sse4.2"
#else
#define FRAMEDYN_BUILD_VECTOR "sse2"
#endif

#if defined(__FMA__)
#define FRAMEDYN_BUILD_FMA " fma"
#else
#define FRAMEDYN_BUILD_FMA ""
#endif

// A macro, not an inline function: each translation unit must expand it with its own flags.
#define FRAMEDYN_BUILD_SIGNATURE                                                                              \
  FRAMEDYN_BUILD_COMPILER "; vector extensions " FRAMEDYN_BUILD_VECTOR FRAMEDYN_BUILD_FMA "; Eigen " FRAMEDYN_STR( \
      EIGEN_WORLD_VERSION) "." FRAMEDYN_STR(EIGEN_MAJOR_VERSION) "." FRAMEDYN_STR(EIGEN_MINOR_VERSION) " max alignment " FRAMEDYN_STR(EIGEN_MAX_ALIGN_BYTES) " bytes"

namespace framedyn::core {

// FRAMEDYN_BUILD_SIGNATURE as the libraries were compiled (core/build_info.cpp).
const char* library_build_signature();

}  // namespace framedyn::core
