/* What lets one header compile as OpenCL C on the device and as C++ on the host: the
 * scalar and vector types of the structs that cross the boundary, and the annotation and
 * types of the few formulas both sides compute (PATHCL_FN, pcl_real, PCL_REAL).
 *
 * Files ending in .h under kernels/ are compiled by both (the host's include path is
 * kernels/); files ending in .cl are device code only. On the host every shared
 * declaration lives in namespace pathcl (PATHCL_BEGIN / PATHCL_END).
 *
 * pcl_real is float on the device and double on the host: the host builds tables (the
 * layer albedo, the sRGB check) from the same formulas in double, the kernels evaluate
 * them in float. PCL_REAL(0.5) is a literal of that type (0.5f on the device). */
#ifndef PATHCL_UTIL_COMPAT_H
#define PATHCL_UTIL_COMPAT_H

#ifdef __OPENCL_C_VERSION__

typedef float4 pcl_float4;
typedef int4 pcl_int4;
typedef float8 pcl_float8;
typedef int8 pcl_int8;
typedef int pcl_int;
typedef uint pcl_uint;
typedef ulong pcl_ulong;
typedef float pcl_float;
typedef float pcl_real;
typedef float3 pcl_real3;
#define PCL_REAL(x) x##f
/* Device helpers are `static inline`: plain `inline` has C99 semantics in OpenCL C and
 * emits no definition, so a call the compiler does not inline fails to link on some
 * drivers (PoCL happens to accept it). */
#define PATHCL_FN static inline
#define PATHCL_BEGIN
#define PATHCL_END
/* PATHCL_ALWAYS_INLINE marks a device function the compiler must inline: a hot function
 * LLVM in PoCL 3.1 left out of line on a CPU, whose call (arguments through memory,
 * nothing overlapped across it) cost more than its code. PATHCL_NOINLINE marks one it must
 * keep out of line: a cold path (the samplers' general draws) that, inlined at every call
 * of a hot function, made a program a third larger and its first build slower, for no
 * speed (measured with `pathcl bench`; the commits that added each mark say by how much).
 * GPU compilers inline every call anyway,
 * so there only PATHCL_NOINLINE changes anything: a call on a cold path. */
#ifdef __clang__
#define PATHCL_ALWAYS_INLINE __attribute__((always_inline))
#define PATHCL_NOINLINE __attribute__((noinline))
#else
#define PATHCL_ALWAYS_INLINE
#define PATHCL_NOINLINE
#endif
/* Every kernel is declared PATHCL_KERNEL. On a device whose compiler vectorizes kernels
 * across work-items and miscompiles that (Intel's CPU runtime passes the float3 arguments
 * of a call it does not inline to the wrong work-items; host/cl/device_workarounds.h), the
 * host defines PATHCL_KERNEL_WIDTH_HINT and each kernel declares the width it already
 * computes in (float8: the BVH's eight lanes), which that compiler does not vectorize
 * further. Elsewhere the hint is left out, and nothing changes. */
#ifdef PATHCL_KERNEL_WIDTH_HINT
#define PATHCL_KERNEL __kernel __attribute__((vec_type_hint(float8)))
#else
#define PATHCL_KERNEL __kernel
#endif

#else

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

namespace pathcl {
struct alignas(16) pcl_float4 {
    float x, y, z, w;
};
struct alignas(32) pcl_float8 {
    float s[8];
};
struct alignas(32) pcl_int8 {
    std::int32_t s[8];
};
struct alignas(16) pcl_int4 {
    std::int32_t x, y, z, w;
};
typedef std::int32_t pcl_int;
typedef std::uint32_t pcl_uint;
typedef std::uint64_t pcl_ulong;
typedef float pcl_float;
typedef double pcl_real;
typedef glm::dvec3 pcl_real3;
#define PCL_REAL(x) x
#define PATHCL_FN inline
#define PATHCL_BEGIN namespace pathcl {
#define PATHCL_END }

/* The OpenCL C built-ins shared formulas use, for the host. */
using std::exp;
using std::fabs;
using std::floor;
using std::fmax;
using std::fmin;
using std::isfinite;
using std::pow;
using std::sqrt;
template <class T>
T clamp(T x, T lo, T hi)
{
    return std::min(std::max(x, lo), hi);
}
} /* namespace pathcl */

#endif

#endif
