// Doubles as text that reads back bit-exactly (shortest round-trip form), shared by the ASCII
// writers, and the matching strict parse for the readers.
#pragma once

#include <charconv>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>

namespace stratamesh {

inline void writeDouble(std::ostream &out, double value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.write(buffer, result.ptr - buffer);
}

inline std::string doubleText(double value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

// The whole token must be a number ("1e5", "-0", "3."); returns false otherwise.
inline bool parseDouble(std::string_view token, double &value)
{
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
    return result.ec == std::errc() && result.ptr == token.data() + token.size() && !token.empty();
}

inline bool parseInt(std::string_view token, long long &value)
{
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
    return result.ec == std::errc() && result.ptr == token.data() + token.size() && !token.empty();
}

} // namespace stratamesh
