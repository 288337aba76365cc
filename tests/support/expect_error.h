// The message of the pathcl::Error that f throws ("" and a test failure when it throws
// nothing or another exception), for the bad-input tests.
#pragma once

#include <exception>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "common/error.h"

namespace pathcl::test {

inline std::string error_of(const std::function<void()>& f)
{
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "threw a std::exception that is not pathcl::Error: " << e.what();
        return "";
    }
    ADD_FAILURE() << "did not throw";
    return "";
}

inline bool contains(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}

} // namespace pathcl::test
