// The one exception type pathcl throws for bad input or a failing device: its message is
// the complete one-line error the CLI prints (it names the file and what is wrong).
#pragma once

#include <stdexcept>
#include <string>

namespace pathcl {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message);
};

// Prints a warning line to stderr ("pathcl: warning: ...").
void warn(const std::string& message);

} // namespace pathcl
