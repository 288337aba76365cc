// Standard error silenced for a scope. Some image libraries print their own lines (libpng's
// "libpng error: ..." before OpenImageIO reports the same error to us) where pathcl
// promises one line per error; their messages still reach us through OpenImageIO's
// geterror(). Used only around image decoding, which runs on the main thread before any
// progress output.
#pragma once

#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace pathcl {

class MutedStderr {
public:
    MutedStderr()
    {
        std::fflush(stderr);
        saved_ = ::dup(STDERR_FILENO);
        int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved_ >= 0 && null >= 0)
            ::dup2(null, STDERR_FILENO);
        if (null >= 0)
            ::close(null);
    }
    ~MutedStderr()
    {
        std::fflush(stderr);
        if (saved_ >= 0) {
            ::dup2(saved_, STDERR_FILENO);
            ::close(saved_);
        }
    }
    MutedStderr(const MutedStderr&) = delete;
    MutedStderr& operator=(const MutedStderr&) = delete;

private:
    int saved_ = -1;
};

} // namespace pathcl
