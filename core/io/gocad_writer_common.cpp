#include "io/gocad_writer_common.h"

#include "io/number_text.h"

namespace stratamesh {

std::string gocadToken(const std::string &name)
{
    std::string clean;
    for (char c : name)
        clean += (c == '"' || c == '\n' || c == '\r') ? '_' : c;
    if (clean.empty())
        return "unnamed";
    if (clean.find_first_of(" \t") != std::string::npos)
        return "\"" + clean + "\"";
    return clean;
}

void writeGocadCoordinateSystem(std::ostream &out, bool zPositiveDepth)
{
    out << "GOCAD_ORIGINAL_COORDINATE_SYSTEM\n"
           "NAME Default\n"
           "AXIS_NAME \"X\" \"Y\" \"Z\"\n"
           "AXIS_UNIT \"m\" \"m\" \"m\"\n"
           "ZPOSITIVE "
        << (zPositiveDepth ? "Depth" : "Elevation") << "\nEND_ORIGINAL_COORDINATE_SYSTEM\n";
}

void writeGocadHeader(std::ostream &out, const std::string &name)
{
    std::string clean;
    for (char c : name)
        clean += (c == '\n' || c == '\r' || c == '}') ? '_' : c;
    out << "HEADER {\nname: " << (clean.empty() ? "unnamed" : clean) << "\n}\n";
}

void writeGocadPoint(std::ostream &out, const Vec3 &p, bool zPositiveDepth)
{
    writeDouble(out, p.x());
    out << ' ';
    writeDouble(out, p.y());
    out << ' ';
    writeDouble(out, zPositiveDepth ? -p.z() : p.z());
}

} // namespace stratamesh
