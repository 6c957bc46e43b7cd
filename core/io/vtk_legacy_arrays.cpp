#include "io/vtk_legacy_arrays.h"
#include "common/translate_noop.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <locale.h>

namespace stratamesh {

namespace {

struct TypeName {
    const char *name;
    VtkLegacyType type;
};

constexpr TypeName typeNames[] = {{"BIT", VtkLegacyType::Bit},
                                  {"CHAR", VtkLegacyType::Char},
                                  {"SIGNED_CHAR", VtkLegacyType::Char},
                                  {"UNSIGNED_CHAR", VtkLegacyType::UnsignedChar},
                                  {"SHORT", VtkLegacyType::Short},
                                  {"UNSIGNED_SHORT", VtkLegacyType::UnsignedShort},
                                  {"INT", VtkLegacyType::Int},
                                  {"UNSIGNED_INT", VtkLegacyType::UnsignedInt},
                                  {"LONG", VtkLegacyType::Long},
                                  {"UNSIGNED_LONG", VtkLegacyType::UnsignedLong},
                                  // VTK's fixed-size names, as meshio writes them.
                                  {"VTKTYPEINT8", VtkLegacyType::Char},
                                  {"VTKTYPEUINT8", VtkLegacyType::UnsignedChar},
                                  {"VTKTYPEINT16", VtkLegacyType::Short},
                                  {"VTKTYPEUINT16", VtkLegacyType::UnsignedShort},
                                  {"VTKTYPEINT32", VtkLegacyType::Int},
                                  {"VTKTYPEUINT32", VtkLegacyType::UnsignedInt},
                                  {"VTKTYPEINT64", VtkLegacyType::Int64},
                                  {"VTKTYPEUINT64", VtkLegacyType::UInt64},
                                  {"VTKIDTYPE", VtkLegacyType::IdType},
                                  {"FLOAT", VtkLegacyType::Float},
                                  {"DOUBLE", VtkLegacyType::Double},
                                  {"STRING", VtkLegacyType::String},
                                  {"UTF8_STRING", VtkLegacyType::String}};

// Bytes per value in a BINARY file (bits are packed: 0 here).
std::size_t binarySize(VtkLegacyType type)
{
    switch (type) {
    case VtkLegacyType::Bit:
    case VtkLegacyType::String:
        return 0;
    case VtkLegacyType::Char:
    case VtkLegacyType::UnsignedChar:
        return 1;
    case VtkLegacyType::Short:
    case VtkLegacyType::UnsignedShort:
        return 2;
    case VtkLegacyType::Int:
    case VtkLegacyType::UnsignedInt:
    case VtkLegacyType::IdType:
    case VtkLegacyType::Float:
        return 4;
    default:
        return 8;
    }
}

std::uint64_t bigEndian(const char *bytes, std::size_t n)
{
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i)
        v = v << 8 | static_cast<unsigned char>(bytes[i]);
    return v;
}

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

// The integer forms C++ streams read ("-12", "+3"), the whole token.
bool parseWhole(std::string_view token, long long &value)
{
    if (token.size() > 1 && token.front() == '+' && isDigit(token[1]))
        token.remove_prefix(1);
    const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
    return !token.empty() && r.ec == std::errc() && r.ptr == token.data() + token.size();
}

bool parseUnsigned(std::string_view token, unsigned long long &value)
{
    if (token.size() > 1 && token.front() == '+' && isDigit(token[1]))
        token.remove_prefix(1);
    const auto r = std::from_chars(token.data(), token.data() + token.size(), value);
    return !token.empty() && r.ec == std::errc() && r.ptr == token.data() + token.size();
}

// "nan", "inf" and their signs, which VTK writes for such values in an ASCII file.
bool parseSpecial(std::string_view token, double &value)
{
    bool negative = false;
    if (!token.empty() && (token.front() == '-' || token.front() == '+')) {
        negative = token.front() == '-';
        token.remove_prefix(1);
    }
    auto is = [&](const char *word) {
        if (token.size() != std::strlen(word))
            return false;
        for (std::size_t i = 0; i < token.size(); ++i)
            if ((token[i] | 0x20) != word[i])
                return false;
        return true;
    };
    if (is("nan"))
        value = std::numeric_limits<double>::quiet_NaN();
    else if (is("inf") || is("infinity"))
        value = negative ? -std::numeric_limits<double>::infinity()
                         : std::numeric_limits<double>::infinity();
    else
        return false;
    return true;
}

// A decimal number as C++ streams read it (sign, digits, point, exponent), rounded to float or
// double as strtof/strtod in the C locale do; false for other text and for an overflow.
template <class Real>
bool parseReal(std::string_view token, Real &value)
{
    std::size_t i = 0;
    if (i < token.size() && (token[i] == '+' || token[i] == '-'))
        ++i;
    std::size_t digits = 0;
    while (i < token.size() && isDigit(token[i]))
        ++i, ++digits;
    if (i < token.size() && token[i] == '.') {
        ++i;
        while (i < token.size() && isDigit(token[i]))
            ++i, ++digits;
    }
    if (digits == 0)
        return false;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
        ++i;
        if (i < token.size() && (token[i] == '+' || token[i] == '-'))
            ++i;
        std::size_t exponent = 0;
        while (i < token.size() && isDigit(token[i]))
            ++i, ++exponent;
        if (exponent == 0)
            return false;
    }
    if (i != token.size())
        return false;
    static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
    const std::string text(token);
    if constexpr (std::is_same_v<Real, float>)
        value = strtof_l(text.c_str(), nullptr, c);
    else
        value = strtod_l(text.c_str(), nullptr, c);
    return std::isfinite(value); // an overflow; an underflow reads as the nearest value
}

// The type's name as files write it ("unsigned_short").
std::string typeText(VtkLegacyType type)
{
    for (const TypeName &t : typeNames)
        if (t.type == type) {
            std::string name = t.name;
            for (char &c : name)
                c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
            return name;
        }
    return "?";
}

// One ASCII value of a numeric type as VTK stores it, read through GetComponent (a double).
// Returns false with `problem` set when the token is not such a value.
bool asciiValue(std::string_view token, VtkLegacyType type, double &value, MessageText &problem)
{
    if (type == VtkLegacyType::Float || type == VtkLegacyType::Double) {
        float f = 0;
        if (type == VtkLegacyType::Float ? parseReal(token, f) : parseReal(token, value)) {
            if (type == VtkLegacyType::Float)
                value = f;
            return true;
        }
        if (parseSpecial(token, value))
            return true;
        problem = {QT_TRANSLATE_NOOP("stratamesh::Core", "is not a number")};
        return false;
    }
    if (type == VtkLegacyType::UnsignedLong || type == VtkLegacyType::UInt64) {
        unsigned long long u = 0;
        if (!parseUnsigned(token, u)) {
            problem = {QT_TRANSLATE_NOOP("stratamesh::Core",
                                         "is not a whole number from 0 to 18446744073709551615")};
            return false;
        }
        value = static_cast<double>(u);
        return true;
    }
    long long v = 0;
    if (!parseWhole(token, v)) {
        problem = {QT_TRANSLATE_NOOP("stratamesh::Core", "is not an integer")};
        return false;
    }
    long long low = std::numeric_limits<int>::min(), high = std::numeric_limits<int>::max();
    switch (type) {
    case VtkLegacyType::Short:
        low = -32768, high = 32767;
        break;
    case VtkLegacyType::UnsignedShort:
        low = 0, high = 65535;
        break;
    case VtkLegacyType::UnsignedInt:
        low = 0, high = 4294967295LL;
        break;
    case VtkLegacyType::Long:
    case VtkLegacyType::Int64:
    case VtkLegacyType::Bit:
        low = std::numeric_limits<long long>::min(), high = std::numeric_limits<long long>::max();
        break;
    default: // chars are read as an int, then cast, as VTK does
        break;
    }
    if (v < low || v > high) {
        problem = {QT_TRANSLATE_NOOP("stratamesh::Core", "is out of range for %1"),
                   {typeText(type)}};
        return false;
    }
    switch (type) {
    case VtkLegacyType::Bit:
        value = v != 0 ? 1 : 0;
        break;
    case VtkLegacyType::Char:
        value = static_cast<signed char>(static_cast<unsigned char>(v & 0xff));
        break;
    case VtkLegacyType::UnsignedChar:
        value = static_cast<unsigned char>(v & 0xff);
        break;
    default:
        value = static_cast<double>(v);
    }
    return true;
}

double binaryValue(const char *bytes, VtkLegacyType type)
{
    const std::uint64_t u = bigEndian(bytes, binarySize(type));
    switch (type) {
    case VtkLegacyType::Char:
        return static_cast<std::int8_t>(static_cast<std::uint8_t>(u));
    case VtkLegacyType::UnsignedChar:
        return static_cast<std::uint8_t>(u);
    case VtkLegacyType::Short:
        return static_cast<std::int16_t>(static_cast<std::uint16_t>(u));
    case VtkLegacyType::UnsignedShort:
        return static_cast<std::uint16_t>(u);
    case VtkLegacyType::Int:
    case VtkLegacyType::IdType:
        return static_cast<std::int32_t>(static_cast<std::uint32_t>(u));
    case VtkLegacyType::UnsignedInt:
        return static_cast<std::uint32_t>(u);
    case VtkLegacyType::Float: {
        const auto bits = static_cast<std::uint32_t>(u);
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    }
    case VtkLegacyType::Double: {
        double d;
        std::memcpy(&d, &u, sizeof d);
        return d;
    }
    case VtkLegacyType::UnsignedLong:
    case VtkLegacyType::UInt64:
        return static_cast<double>(u);
    default:
        return static_cast<double>(static_cast<std::int64_t>(u));
    }
}

// Fails unless the BINARY data of `count` values of `size` bytes (bits when 0) is all there.
std::size_t needBytes(VtkLegacyCursor &in, const VtkValuesAt &at, long long count, std::size_t size)
{
    const auto n = static_cast<unsigned long long>(count);
    const bool fits =
        count >= 0 && (size == 0 ? (n + 7) / 8 <= in.remaining() : n <= in.remaining() / size);
    if (!fits)
        in.fail(at.headerLine,
                size == 0
                    ? MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                    "%1 data is cut short: %2 bits, %3 bytes "
                                                    "are left"),
                                  {at.what, std::to_string(count), std::to_string(in.remaining())}}
                    : MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                    "%1 data is cut short: %2 values of %3 "
                                                    "bytes, %4 bytes are left"),
                                  {at.what, std::to_string(count), std::to_string(size),
                                   std::to_string(in.remaining())}});
    return size == 0 ? static_cast<std::size_t>((n + 7) / 8) : static_cast<std::size_t>(n) * size;
}

// Refuses an ASCII count that cannot fit in the rest of the file (a value takes a byte at least).
void needText(VtkLegacyCursor &in, const VtkValuesAt &at, long long count)
{
    if (count < 0 || static_cast<unsigned long long>(count) > in.remaining())
        in.fail(at.headerLine,
                MessageText{QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "%1 declares %2 values, more than the file of %3 bytes can hold"),
                            {at.what, std::to_string(count), std::to_string(in.fileSize())}});
}

// Reads `count` ASCII tokens through `take(token, index)`, which returns an empty string or why
// the token is not a value; then the line of the last value must end.
template <class Take>
void readTokens(VtkLegacyCursor &in, const VtkValuesAt &at, long long count, Take take)
{
    int last = at.headerLine;
    for (long long i = 0; i < count; ++i) {
        const std::string_view token = in.token();
        if (token.empty())
            in.fail(last,
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "%1 declares %2 values, the file ends after %3"),
                                {at.what, std::to_string(count), std::to_string(i)}});
        MessageText problem = take(token, i);
        if (!problem.pattern.empty()) {
            const bool word = (token[0] >= 'A' && token[0] <= 'Z') || token[0] == '_'
                              || (token[0] >= 'a' && token[0] <= 'z');
            if (word)
                in.fail(
                    in.tokenLine(),
                    MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "%1 declares %2 values, \"%3\" comes after %4"),
                        {at.what, std::to_string(count), vtkPrintable(token), std::to_string(i)}});
            in.fail(in.tokenLine(),
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 value '%2' %3"),
                                {at.what, vtkPrintable(token)},
                                {std::move(problem)}});
        }
        last = in.tokenLine();
    }
    if (count > 0 && !in.restOfLineBlank())
        in.fail(last, MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                    "%1 declares %2 values, the line holds more"),
                                  {at.what, std::to_string(count)}});
}

} // namespace

std::optional<VtkLegacyType> vtkLegacyType(std::string_view name)
{
    for (const TypeName &t : typeNames)
        if (vtkKeywordIs(name, t.name))
            return t.type;
    return std::nullopt;
}

std::vector<double> readVtkNumbers(VtkLegacyCursor &in, const VtkValuesAt &at, VtkLegacyType type,
                                   long long count, std::vector<int> *lines)
{
    std::vector<double> values;
    if (at.binary) {
        const std::size_t size = binarySize(type);
        const std::string_view raw = in.bytes(needBytes(in, at, count, size));
        const auto n = static_cast<std::size_t>(count);
        values.reserve(n);
        for (std::size_t i = 0; i < n; ++i)
            values.push_back(size > 0
                                 ? binaryValue(raw.data() + i * size, type)
                                 : (static_cast<unsigned char>(raw[i / 8]) >> (7 - i % 8)) & 1);
        return values;
    }
    needText(in, at, count);
    values.reserve(static_cast<std::size_t>(count));
    readTokens(in, at, count, [&](std::string_view token, long long) {
        double v = 0;
        MessageText problem;
        if (!asciiValue(token, type, v, problem))
            return problem;
        values.push_back(v);
        if (lines)
            lines->push_back(in.tokenLine());
        return MessageText();
    });
    return values;
}

std::vector<long long> readVtkIntegers(VtkLegacyCursor &in, const VtkValuesAt &at, int bytes,
                                       long long count, std::vector<int> *lines)
{
    std::vector<long long> values;
    if (at.binary) {
        const auto size = static_cast<std::size_t>(bytes);
        const std::string_view raw = in.bytes(needBytes(in, at, count, size));
        const auto n = static_cast<std::size_t>(count);
        values.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint64_t u = bigEndian(raw.data() + i * size, size);
            values.push_back(bytes == 4 ? static_cast<std::int32_t>(static_cast<std::uint32_t>(u))
                                        : static_cast<long long>(u));
        }
        return values;
    }
    needText(in, at, count);
    values.reserve(static_cast<std::size_t>(count));
    readTokens(in, at, count, [&](std::string_view token, long long) {
        long long v = 0;
        if (!parseWhole(token, v))
            return MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "is not an integer")};
        if (bytes == 4
            && (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()))
            return MessageText{
                QT_TRANSLATE_NOOP("stratamesh::Core", "is out of range for a 4-byte integer")};
        values.push_back(v);
        if (lines)
            lines->push_back(in.tokenLine());
        return MessageText();
    });
    return values;
}

std::vector<std::string> readVtkStrings(VtkLegacyCursor &in, const VtkValuesAt &at, long long count)
{
    // A string takes one byte at least: its length in BINARY, its end of line in ASCII.
    if (count < 0 || static_cast<unsigned long long>(count) > in.remaining())
        in.fail(at.headerLine,
                MessageText{QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "%1 declares %2 strings, more than the file of %3 bytes can hold"),
                            {at.what, std::to_string(count), std::to_string(in.fileSize())}});
    std::vector<std::string> strings;
    strings.reserve(static_cast<std::size_t>(count));
    for (long long i = 0; i < count; ++i) {
        if (!at.binary) {
            std::string_view text;
            if (!in.line(text))
                in.fail(
                    in.tokenLine(),
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "%1 declares %2 strings, the file ends after %3"),
                                {at.what, std::to_string(count), std::to_string(i)}});
            strings.push_back(vtkDecodedName(text));
            continue;
        }
        // VTK's length prefix: the top two bits of the first byte say how many bytes it has.
        auto cut = [&] {
            in.fail(at.headerLine,
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core",
                                                  "%1 data is cut short in string %2 of %3"),
                                {at.what, std::to_string(i + 1), std::to_string(count)}});
        };
        if (in.remaining() < 1)
            cut();
        const auto first = static_cast<unsigned char>(in.bytes(1)[0]);
        const std::size_t more = first >> 6 == 3   ? 0
                                 : first >> 6 == 2 ? 1
                                 : first >> 6 == 1 ? 3
                                                   : 7;
        if (in.remaining() < more)
            cut();
        const std::uint64_t length =
            std::uint64_t(first & 0x3f) << (8 * more) | bigEndian(in.bytes(more).data(), more);
        if (length > in.remaining())
            cut();
        strings.emplace_back(in.bytes(static_cast<std::size_t>(length)));
    }
    return strings;
}

void skipVtkMetadata(VtkLegacyCursor &in, int components)
{
    if (!vtkKeywordIs(in.peekToken(), "METADATA"))
        return;
    in.token();
    in.endLine("METADATA");
    std::string_view text;
    while (in.line(text) && !text.empty()) {
        if (vtkKeywordIs(text.substr(0, 15), "COMPONENT_NAMES"))
            for (int k = 0; k < components && in.line(text); ++k) {
            }
    }
}

std::string vtkDecodedName(std::string_view name)
{
    auto hex = [](char c) {
        return c >= '0' && c <= '9'   ? c - '0'
               : c >= 'a' && c <= 'f' ? c - 'a' + 10
               : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                      : -1;
    };
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        if (name[i] == '%' && i + 2 < name.size() && hex(name[i + 1]) >= 0
            && hex(name[i + 2]) >= 0) {
            out += static_cast<char>(hex(name[i + 1]) * 16 + hex(name[i + 2]));
            i += 2;
        } else {
            out += name[i];
        }
    }
    return out;
}

} // namespace stratamesh
