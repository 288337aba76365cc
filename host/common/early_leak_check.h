// LeakSanitizer's leak check, run early: the pathcl binary calls it at the end of main,
// the test binaries once their tests are done (tests/support/early_leak_check.cpp),
// before any library's static destructors. Left to exit, the check runs after them, and
// what a library keeps for the whole process in a static container reads as leaked once
// the container is gone: PoCL's kernel compiler keeps its LLVM pass managers in a static
// map and never frees them (16 bytes direct, megabytes indirect, from libpocl, whenever a
// run compiles a work-group function PoCL has not cached). A leak of ours is one at both
// points: the caller's own objects are destroyed by then. Once it has run, the check at
// exit does nothing. Without AddressSanitizer it does nothing.
#pragma once

#if defined(__SANITIZE_ADDRESS__) // GCC
#define PATHCL_ADDRESS_SANITIZER 1
#elif defined(__has_feature) // Clang
#if __has_feature(address_sanitizer)
#define PATHCL_ADDRESS_SANITIZER 1
#endif
#endif

#ifdef PATHCL_ADDRESS_SANITIZER
#include <sanitizer/lsan_interface.h>
#endif

namespace pathcl {

inline void check_leaks_now()
{
#ifdef PATHCL_ADDRESS_SANITIZER
    __lsan_do_leak_check();
#endif
}

} // namespace pathcl
