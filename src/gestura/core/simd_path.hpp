#pragma once
// Which implementation of a SIMD kernel runs: the portable one (SSE2 on x86-64, plain C++ elsewhere)
// or the AVX2+FMA one, chosen at run time when the CPU has both (Auto). Kernels with both paths
// (skinning, blending, clip decompression) agree within 1e-5: FMA rounding, and estimates refined
// by a Newton step where the portable path divides.
#include <cstdint>

#if defined(__x86_64__) || defined(__i386__)
#define GESTURA_HAS_AVX2_PATH 1
#endif

namespace gestura {

enum class SimdPath : std::uint8_t { Auto, Portable, Avx2 };

// True when this CPU runs AVX2 and FMA instructions.
bool cpu_has_avx2_fma();

// Auto → the best available path. Avx2 on a CPU without it throws gestura::Error naming `what`.
SimdPath resolve_simd_path(SimdPath requested, const char* what);

}  // namespace gestura
