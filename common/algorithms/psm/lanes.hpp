#pragma once
// Two doubles in one vector register (SSE2 on x86-64, NEON on Arm; GCC's and Clang's vector
// extensions) for the hot loops of the light-camera set-up (bench_psm_setup). Lane-wise IEEE
// arithmetic: written in the scalar code's order of operations, a loop gives the scalar digits.
#include <cstdint>

namespace shadowlab::psm::lanes {

using V2 = double __attribute__((vector_size(16)));
using M2 = std::int64_t __attribute__((vector_size(16)));  // a comparison's lanes: all ones or zero

inline V2 splat(double v) { return V2{v, v}; }
// yes where mask is set, else no: bitwise, so signed zeros and NaNs pass unchanged.
inline V2 pick(M2 mask, V2 yes, V2 no) { return V2((M2(yes) & mask) | (M2(no) & ~mask)); }
inline bool both(M2 mask) { return (mask[0] & mask[1]) != 0; }

}  // namespace shadowlab::psm::lanes
