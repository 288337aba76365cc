// Pieces of the text the user or a file gives: comma-separated lists and whole numbers.
// Shared by the flags that take lists (--device, --vary) and the metadata of partial
// renders.
#pragma once

#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pathcl {

// The items between commas, empty ones kept ("a,,b" is three items; "" one), so the
// caller's check of each item also refuses a stray comma.
inline std::vector<std::string> split_commas(const std::string& text)
{
    std::vector<std::string> items;
    std::size_t at = 0;
    for (;;) {
        const std::size_t comma = text.find(',', at);
        items.push_back(text.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
        if (comma == std::string::npos)
            return items;
        at = comma + 1;
    }
}

// A whole number written in decimal digits only (no sign, space or exponent) of at most
// `max`; nothing otherwise, overflow included.
inline std::optional<std::uint64_t> parse_whole_number(const std::string& text, std::uint64_t max = UINT64_MAX)
{
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    auto [stop, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc() || stop != end || v > max)
        return std::nullopt;
    return v;
}

} // namespace pathcl
