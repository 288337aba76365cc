/* PATHCL_PREFETCH(p): starts the cache line at p on its way into the cache without waiting
 * for it, where the compiler can say so. OpenCL's prefetch() may do nothing (PoCL's does),
 * and a volatile read, which stays where prefetch() would not, holds a CPU core's
 * retirement until its line arrives: reading ahead the record of a light picked from a
 * hundred thousand that way, the wait took 7 % of the render's time (`perf`, the glowing
 * sphere of tools/make_many_lights.py, the light tree). Clang compiling for x86-64 (PoCL
 * on a CPU) takes the instruction itself; elsewhere PATHCL_PREFETCH stays undefined and
 * callers read ahead with volatile loads. */
#ifndef PATHCL_UTIL_PREFETCH_CL
#define PATHCL_UTIL_PREFETCH_CL

#if defined(__clang__) && defined(__x86_64__)
#define PATHCL_PREFETCH(p) __asm__ volatile("prefetcht0 %0" : : "m"(*(__global const char*)(p)))
#endif

#endif /* PATHCL_UTIL_PREFETCH_CL */
