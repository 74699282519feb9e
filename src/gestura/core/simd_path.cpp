#include "gestura/core/simd_path.hpp"

#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

bool cpu_has_avx2_fma() {
#ifdef GESTURA_HAS_AVX2_PATH
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
#else
  return false;
#endif
}

SimdPath resolve_simd_path(SimdPath requested, const char* what) {
  if (requested == SimdPath::Auto) return cpu_has_avx2_fma() ? SimdPath::Avx2 : SimdPath::Portable;
  if (requested == SimdPath::Avx2 && !cpu_has_avx2_fma())
    throw Error(std::string(what) + ": the AVX2+FMA path was requested but this CPU does not support it");
  return requested;
}

}  // namespace gestura
