// The exceptions pathcl throws for bad input or a failing device: the message is the
// complete one-line error (it names the file, or the parameter, and what is wrong).
#pragma once

#include <cstddef>
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

// A string that came from a file or the command line, as an error quotes it: between
// double quotes, with control characters, quotes and backslashes escaped (\n, \", \\,
// \xHH) and at most kMaxQuotedBytes of it kept (then "..." and its full length), so that
// no string can break an error's one line or bury it.
constexpr std::size_t kMaxQuotedBytes = 80;
std::string quote(const std::string& text);

// A whole message as it is printed: every control character escaped (one line whatever
// a message quotes) and cut after kMaxMessageBytes. main() and warn() print through it.
constexpr std::size_t kMaxMessageBytes = 4096;
std::string printable_line(const std::string& message);

// Prints a warning line to stderr ("pathcl: warning: ...").
void warn(const std::string& message);

} // namespace pathcl
