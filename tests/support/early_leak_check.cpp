// In a sanitizer build, the test binaries check for leaks once their tests are done, while
// the libraries' thread pools (OpenEXR's, OpenImageIO's, PoCL's) still sit idle, as the
// pathcl binary does (host/cli/main.cpp): LeakSanitizer's check at exit runs after their
// static destructors have stopped those threads, and its tracer can crash on a thread
// still ending (github.com/google/sanitizers/issues/1353).
#include <gtest/gtest.h>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>

namespace {

class EarlyLeakCheck : public ::testing::Environment {
public:
    void TearDown() override { __lsan_do_leak_check(); }
};

const ::testing::Environment* const kEarlyLeakCheck = ::testing::AddGlobalTestEnvironment(new EarlyLeakCheck);

} // namespace
#endif
