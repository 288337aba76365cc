/* cache_line_warm(p): starts the cache line that holds the word at p on its way into the
 * cache. OpenCL's prefetch() may do nothing (PoCL's does); a volatile read of the word
 * stays, but holds a CPU core's retirement until its line arrives: reading ahead the
 * record of a light picked from a hundred thousand that way, the wait took 7 % of the
 * render's time (`perf`, the glowing sphere of tools/make_many_lights.py, the light
 * tree). So where the compiler can say so (clang compiling for x86-64: PoCL on a CPU),
 * PATHCL_PREFETCH is defined and the line is prefetched without a wait; elsewhere the
 * word is read, volatile. */
#ifndef PATHCL_UTIL_PREFETCH_CL
#define PATHCL_UTIL_PREFETCH_CL

#if defined(__clang__) && defined(__x86_64__)
#define PATHCL_PREFETCH(p) __asm__ volatile("prefetcht0 %0" : : "m"(*(__global const char*)(p)))
#endif

static inline void cache_line_warm(__global const int* p)
{
#ifdef PATHCL_PREFETCH
    PATHCL_PREFETCH(p);
#else
    (void)*(volatile __global const int*)p;
#endif
}

#ifdef PATHCL_PREFETCH
/* Starts every cache line of the `bytes` bytes at p on its way into the cache. Only where
 * a line is started without a wait: volatile reads of several lines would wait for each. */
static inline void cache_lines_warm(__global const int* p, uint bytes)
{
    const uint words = bytes / (uint)sizeof(int);
    for (uint w = 0; w < words; w += 16u) /* 64-byte lines */
        cache_line_warm(p + w);
    cache_line_warm(p + words - 1u); /* the last line, where p is not on a line's start */
}
#endif

#endif /* PATHCL_UTIL_PREFETCH_CL */
