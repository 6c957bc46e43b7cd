#include "io/vtk_xml_counts.h"

#include "common/error.h"
#include "io/number_text.h"

#include <algorithm>
#include <fstream>
#include <iterator>

namespace stratamesh {

namespace {

constexpr long long maxExpansion = 1032;

} // namespace

void checkVtkXmlCounts(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw FileError(path, 0, "cannot open the file");
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
                throw FileError(path, line, std::string(name) + " is not a whole number");
            if (n < 0)
                throw FileError(path, line,
                                std::string(name) + " is negative (" + std::to_string(n) + ")");
            if (n / maxExpansion > size)
                throw FileError(path, line,
                                std::string(name) + " is " + std::to_string(n)
                                    + ", more than the file of " + std::to_string(size)
                                    + " bytes can hold even compressed");
        }
    }
}

} // namespace stratamesh
