// The AVX2 instantiation of the playback kernel (8 tracks per block). Built with -mavx2 -mfma
// -ffp-contract=off (CMakeLists.txt, files named *.avx2.cpp), so it computes exactly what the
// portable path computes; called only after cpu_has_avx2_fma().
#include "gestura/compress/playback_kernel.hpp"

namespace gestura::playback_detail {

#if defined(GESTURA_SIMD_HAS_F8)
void sample_avx2(const Group& group, std::uint32_t frame, float x, float* out) { sample_group<F8>(group, frame, x, out); }
#endif

}  // namespace gestura::playback_detail
