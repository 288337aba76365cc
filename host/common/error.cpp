#include "common/error.h"

#include <iostream>

namespace pathcl {
namespace {

// "<parameter>: <detail>" with each {name} in the detail replaced by name(name).
std::string compose(const std::string& parameter, const std::string& detail,
                    const std::function<std::string(const std::string&)>& name)
{
    std::string out = name(parameter) + ": ";
    for (std::size_t i = 0; i < detail.size(); ++i) {
        std::size_t close = detail[i] == '{' ? detail.find('}', i) : std::string::npos;
        if (close == std::string::npos) {
            out += detail[i];
            continue;
        }
        out += name(detail.substr(i + 1, close - i - 1));
        i = close;
    }
    return out;
}

std::string as_is(const std::string& parameter)
{
    return parameter;
}

} // namespace

std::string one_line(std::string text)
{
    for (char& c : text)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

Error::Error(const std::string& message) : std::runtime_error(message)
{}

ParameterError::ParameterError(const std::string& parameter, const std::string& detail)
    : Error(compose(parameter, detail, as_is)), parameter_(parameter), detail_(detail)
{}

std::string ParameterError::describe(const std::function<std::string(const std::string&)>& name) const
{
    return compose(parameter_, detail_, name);
}

void warn(const std::string& message)
{
    std::cerr << "pathcl: warning: " << message << '\n';
}

} // namespace pathcl
