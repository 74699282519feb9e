// The AVX2+FMA instantiation of the blending kernel (8 joints per block). Built with -mavx2 -mfma
// (CMakeLists.txt, files named *.avx2.cpp) and called only after cpu_has_avx2_fma(); it includes
// nothing but the kernel, whose helpers have internal linkage.
#include "gestura/anim/blend_kernel.hpp"

namespace gestura::blend_detail {

#if defined(GESTURA_SIMD_HAS_F8)
void run_avx2(const BlendJob& job) { run<F8>(job); }
bool plan_avx2(const PlanJob& job) { return plan<F8>(job); }
#endif

}  // namespace gestura::blend_detail
