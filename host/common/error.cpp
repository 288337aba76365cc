#include "common/error.h"

#include <iostream>

namespace pathcl {

Error::Error(const std::string& message) : std::runtime_error(message) {}

void warn(const std::string& message)
{
    std::cerr << "pathcl: warning: " << message << '\n';
}

} // namespace pathcl
