// LeakSanitizer's leak check, run early: the pathcl binary calls it at the end of main,
// the test binaries once their tests are done (tests/support/early_leak_check.cpp), while
// the libraries' thread pools (OpenEXR's, OpenImageIO's, PoCL's) sit idle. Left to exit,
// the check runs after their static destructors have stopped those threads, and its
// tracer can crash on a thread that is still ending ("Tracer caught signal 11",
// github.com/google/sanitizers/issues/1353; it still can here, rarely, on a thread a
// library ends by itself, which tools/test.sh meets with one rerun). A leak is one at
// both points: the caller's own objects are destroyed by then, and what the libraries'
// statics hold is still reachable from them. Once it has run, the check at exit does
// nothing. Without AddressSanitizer it does nothing.
#pragma once

#if defined(__SANITIZE_ADDRESS__) // GCC
#define PATHCL_EARLY_LEAK_CHECK 1
#elif defined(__has_feature) // Clang
#if __has_feature(address_sanitizer)
#define PATHCL_EARLY_LEAK_CHECK 1
#endif
#endif

#ifdef PATHCL_EARLY_LEAK_CHECK
#include <sanitizer/lsan_interface.h>
#endif

namespace pathcl {

inline void check_leaks_now()
{
#ifdef PATHCL_EARLY_LEAK_CHECK
    __lsan_do_leak_check();
#endif
}

} // namespace pathcl
