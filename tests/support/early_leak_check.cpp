// In a sanitizer build, the test binaries check for leaks once their tests are done,
// before the libraries' static destructors run (common/early_leak_check.h).
#include "common/early_leak_check.h"

#include <gtest/gtest.h>

namespace {

class EarlyLeakCheck : public ::testing::Environment {
public:
    void TearDown() override { pathcl::check_leaks_now(); }
};

const ::testing::Environment* const kEarlyLeakCheck = ::testing::AddGlobalTestEnvironment(new EarlyLeakCheck);

} // namespace
