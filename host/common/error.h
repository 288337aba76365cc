// The exceptions pathcl throws for bad input or a failing device: the message is the
// complete one-line error (it names the file, or the parameter, and what is wrong).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace pathcl {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message);
};

// A bad value of one named parameter of a request (a render option, a camera override):
// what() reads "<parameter>: <detail>". The detail may name other parameters as
// {parameter}. The library speaks only of parameters; a front end names them its own way
// (the CLI: by their flags, flag_for in host/cli/options.cpp) through describe().
class ParameterError : public Error {
public:
    ParameterError(const std::string& parameter, const std::string& detail);

    const std::string& parameter() const { return parameter_; }
    // The message with every parameter (this one and those in the detail) named by `name`.
    std::string describe(const std::function<std::string(const std::string&)>& name) const;

private:
    std::string parameter_, detail_;
};

// `text` on one line: line breaks become spaces, trailing blanks go (for the messages of
// libraries, which end in or contain newlines).
std::string one_line(std::string text);

// Prints a warning line to stderr ("pathcl: warning: ...").
void warn(const std::string& message);

} // namespace pathcl
