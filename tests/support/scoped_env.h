// An environment variable set for a scope: the previous value (or its absence) comes back
// when the scope ends. For the tests that point pathcl at a private cache directory.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>

namespace pathcl::test {

class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name)
    {
        if (const char* old = std::getenv(name))
            saved_ = old;
        set(value);
    }
    ~ScopedEnv()
    {
        if (saved_)
            ::setenv(name_.c_str(), saved_->c_str(), 1);
        else
            ::unsetenv(name_.c_str());
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

    void set(const std::string& value) { ::setenv(name_.c_str(), value.c_str(), 1); }

private:
    std::string name_;
    std::optional<std::string> saved_;
};

} // namespace pathcl::test
