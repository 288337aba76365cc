// Default AddressSanitizer options of the sanitizer build (-DPATHCL_SANITIZE=ON), compiled
// into each of its programs (the pathcl binary, the test binaries, the fuzz targets);
// ASAN_OPTIONS still overrides them. Without AddressSanitizer this file defines nothing.
//
// intercept_tls_get_addr=0: GCC 12's runtime (Debian 12) takes a dynamic TLS block that
// malloc happens to place 16 bytes into a page for the layout of glibc 2.18 and older, and
// reads the two words before it, an allocator header, as the block's bounds. LeakSanitizer
// then scans that range and its tracer dies ("Tracer caught signal 11" at a small address
// such as 0x4698, in ScanRangeForPointers; google/sanitizers#1322). Where the blocks land
// depends only on the allocations before, so a run that meets it meets it every time
// (tests/sanitizer/tls_probe.cpp makes one). Without the interception a dynamic TLS block
// that malloc made is still scanned as the heap block it is: what only such a block
// points to is not reported, what nothing points to is.
#include "common/early_leak_check.h" // PATHCL_ADDRESS_SANITIZER

#ifdef PATHCL_ADDRESS_SANITIZER
extern "C" const char* __asan_default_options();

extern "C" const char* __asan_default_options()
{
    return "intercept_tls_get_addr=0";
}
#endif
