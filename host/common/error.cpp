#include "common/error.h"

#include <algorithm>
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

// c escaped when it is a control character (or, with quotes, a quote or a backslash).
void append_escaped(std::string& out, char c, bool quotes)
{
    const unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u != 0x7f && !(quotes && (c == '"' || c == '\\'))) {
        out += c;
        return;
    }
    switch (c) {
    case '\n':
        out += "\\n";
        return;
    case '\r':
        out += "\\r";
        return;
    case '\t':
        out += "\\t";
        return;
    case '"':
        out += "\\\"";
        return;
    case '\\':
        out += "\\\\";
        return;
    default:
        break;
    }
    static const char hex[] = "0123456789abcdef";
    out += "\\x";
    out += hex[u >> 4];
    out += hex[u & 15];
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

std::string quote(const std::string& text)
{
    std::string out = "\"";
    std::size_t kept = std::min(text.size(), kMaxQuotedBytes);
    while (kept < text.size() && kept > 0 && (static_cast<unsigned char>(text[kept]) & 0xc0) == 0x80)
        --kept; // not inside a UTF-8 character
    for (std::size_t i = 0; i < kept; ++i)
        append_escaped(out, text[i], true);
    out += '"';
    if (kept < text.size())
        out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

std::string printable_line(const std::string& message)
{
    std::string out;
    const std::size_t kept = std::min(message.size(), kMaxMessageBytes);
    for (std::size_t i = 0; i < kept; ++i)
        append_escaped(out, message[i], false);
    if (kept < message.size())
        out += "... (" + std::to_string(message.size() - kept) + " more bytes)";
    return out;
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
    std::cerr << "pathcl: warning: " << printable_line(message) << '\n';
}

} // namespace pathcl
