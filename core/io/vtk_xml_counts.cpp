#include "io/vtk_xml_counts.h"

#include "common/error.h"
#include "common/translate_noop.h"
#include "io/number_text.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <set>

namespace stratamesh {

namespace {

constexpr long long maxExpansion = 1032;

// Base64 digits of `text` from `at` (whitespace skipped) decoded until `bytes` bytes are known.
std::string decodeBase64Prefix(const std::string &text, std::size_t at, std::size_t bytes)
{
    static const std::string digits =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    unsigned value = 0;
    int bits = 0;
    for (; at < text.size() && out.size() < bytes; ++at) {
        const std::size_t d = digits.find(text[at]);
        if (text[at] == '<' || text[at] == '=')
            break;
        if (d == std::string::npos)
            continue;
        value = (value << 6) | unsigned(d);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += char((value >> bits) & 0xff);
        }
    }
    return out;
}

unsigned long long headerValue(const std::string &bytes, std::size_t index, std::size_t width,
                               bool bigEndian)
{
    unsigned long long v = 0;
    for (std::size_t k = 0; k < width; ++k) {
        const std::size_t at = index * width + (bigEndian ? k : width - 1 - k);
        v = (v << 8) | static_cast<unsigned char>(bytes[at]);
    }
    return v;
}

// The block header of each compressed inline array (blocks, block size, last block size, then the
// compressed sizes): VTK 9.1 allocates the sizes it states before inflating anything.
void checkCompressionHeaders(const std::string &path, const std::string &text, long long size)
{
    const std::size_t root = text.find("<VTKFile");
    if (root == std::string::npos)
        return;
    const std::string rootTag = text.substr(root, text.find('>', root) - root);
    if (rootTag.find("compressor=") == std::string::npos)
        return;
    const std::size_t width = rootTag.find("header_type=\"UInt64\"") != std::string::npos ? 8 : 4;
    const bool bigEndian = rootTag.find("BigEndian") != std::string::npos;
    for (std::size_t at = text.find("<DataArray"); at != std::string::npos;
         at = text.find("<DataArray", at + 1)) {
        const std::size_t close = text.find('>', at);
        if (close == std::string::npos)
            return;
        if (text.substr(at, close - at).find("format=\"binary\"") == std::string::npos)
            continue;
        const int line =
            1 + static_cast<int>(std::count(text.begin(), text.begin() + long(at), '\n'));
        const std::string head = decodeBase64Prefix(text, close + 1, 3 * width);
        if (head.size() < 3 * width)
            continue; // too short: VTK says so itself
        const unsigned long long blocks = headerValue(head, 0, width, bigEndian);
        const unsigned long long blockSize = headerValue(head, 1, width, bigEndian);
        const unsigned long long last = headerValue(head, 2, width, bigEndian);
        const auto limit = static_cast<unsigned long long>(size);
        if (blocks > limit || blockSize > limit * maxExpansion || last > blockSize
            || (blocks > 0 && blockSize > 0 && blocks - 1 > limit * maxExpansion / blockSize))
            throw FileError(
                path, line,
                MessageText{QT_TRANSLATE_NOOP(
                                "stratamesh::Core",
                                "the header of a compressed array is damaged or too large: %1 "
                                "blocks of %2 bytes, the last of %3, in a file of %4 bytes"),
                            {std::to_string(blocks), std::to_string(blockSize),
                             std::to_string(last), std::to_string(size)}});
        // VTK 9.1 reads data after a header of no block as if it had one (SEGV).
        if (blocks == 0) {
            std::string body = text.substr(close + 1, text.find('<', close + 1) - close - 1);
            body.erase(std::remove_if(body.begin(), body.end(),
                                      [](unsigned char c) { return std::isspace(c) != 0; }),
                       body.end());
            if (body.size() > (3 * width + 2) / 3 * 4)
                throw FileError(
                    path, line,
                    QT_TRANSLATE_NOOP("stratamesh::Core",
                                      "a compressed array states no block but holds data"));
        }
        // Each block's compressed size is read (allocated) as stated: none exceeds the file.
        const std::string all = decodeBase64Prefix(text, close + 1, (3 + blocks) * width);
        if (all.size() < (3 + blocks) * width)
            throw FileError(path, line,
                            QT_TRANSLATE_NOOP("stratamesh::Core",
                                              "the header of a compressed array is cut short"));
        for (unsigned long long b = 0; b < blocks; ++b)
            if (headerValue(all, 3 + b, width, bigEndian) > limit)
                throw FileError(
                    path, line,
                    MessageText{
                        QT_TRANSLATE_NOOP("stratamesh::Core",
                                          "block %1 of a compressed array states %2 compressed "
                                          "bytes, more than the file of %3 bytes"),
                        {std::to_string(b + 1),
                         std::to_string(headerValue(all, 3 + b, width, bigEndian)),
                         std::to_string(size)}});
    }
}

} // namespace

void checkVtkXmlCounts(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw FileError(path, 0, QT_TRANSLATE_NOOP("stratamesh::Core", "cannot open the file"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const long long size = static_cast<long long>(text.size());
    // Raw appended data may hold any bytes: only the XML before it declares sizes.
    const std::size_t appended = text.find("<AppendedData");
    if (appended != std::string::npos)
        text.resize(appended);
    const char *names[] = {"NumberOfPoints",     "NumberOfCells",  "NumberOfVerts",
                           "NumberOfLines",      "NumberOfStrips", "NumberOfPolys",
                           "NumberOfComponents", "NumberOfTuples"};
    for (const char *name : names) {
        const std::string key = std::string(name) + "=\"";
        for (std::size_t at = text.find(key); at != std::string::npos;
             at = text.find(key, at + 1)) {
            const std::size_t begin = at + key.size();
            const std::size_t end = text.find('"', begin);
            long long n = 0;
            const int line =
                1 + static_cast<int>(std::count(text.begin(), text.begin() + long(at), '\n'));
            if (end == std::string::npos
                || !parseInt(std::string_view(text).substr(begin, end - begin), n))
                throw FileError(
                    path, line,
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 is not a whole number"),
                                {std::string(name)}});
            if (n < 0)
                throw FileError(
                    path, line,
                    MessageText{QT_TRANSLATE_NOOP("stratamesh::Core", "%1 is negative (%2)"),
                                {std::string(name), std::to_string(n)}});
            if (n / maxExpansion > size)
                throw FileError(
                    path, line,
                    MessageText{
                        QT_TRANSLATE_NOOP(
                            "stratamesh::Core",
                            "%1 is %2, more than the file of %3 bytes can hold even compressed"),
                        {std::string(name), std::to_string(n), std::to_string(size)}});
        }
    }
    checkCompressionHeaders(path, text, size);
    // VTK 9.1 dereferences the array it could not make for an unknown type.
    static const std::set<std::string> types{
        "Int8",    "UInt8",   "Int16",  "UInt16", "Int32", "UInt32", "Int64",  "UInt64",
        "Float32", "Float64", "String", "Bit",    "Char",  "Float",  "Double", "IdType"};
    for (std::size_t at = text.find("<DataArray"); at != std::string::npos;
         at = text.find("<DataArray", at + 1)) {
        const std::string tag = text.substr(at, text.find('>', at) - at);
        const std::size_t type = tag.find(" type=\"");
        const std::string name = type == std::string::npos
                                     ? std::string()
                                     : tag.substr(type + 7, tag.find('"', type + 7) - type - 7);
        if (types.count(name) == 0) {
            const int line =
                1 + static_cast<int>(std::count(text.begin(), text.begin() + long(at), '\n'));
            throw FileError(path, line,
                            MessageText{QT_TRANSLATE_NOOP(
                                            "stratamesh::Core",
                                            "a DataArray has type \"%1\", which is not a VTK type"),
                                        {name}});
        }
    }
}

} // namespace stratamesh
