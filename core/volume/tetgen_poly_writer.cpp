#include "volume/tetgen_poly_writer.h"

#include "io/atomic_file.h"
#include "io/number_text.h"

#include <ostream>

namespace stratamesh {

void writeTetgenPoly(const Plc &plc, const std::string &path)
{
    writeTextFileAtomically(path, [&](std::ostream &out) {
        out << "# StrataMesh PLC: " << plc.points.size() << " points, " << plc.facets.size()
            << " facets (marker = surface index + 1), " << plc.regions.size() << " regions\n";
        out << "# Part 1 - nodes: count, dimension, attributes, boundary markers\n";
        out << plc.points.size() << " 3 0 0\n";
        for (std::size_t i = 0; i < plc.points.size(); ++i) {
            out << i + 1;
            for (int k = 0; k < 3; ++k) {
                out << ' ';
                writeDouble(out, plc.points[i][k]);
            }
            out << '\n';
        }
        out << "# Part 2 - facets: count, boundary markers; each: polygons holes marker, polygon\n";
        out << plc.facets.size() << " 1\n";
        for (std::size_t f = 0; f < plc.facets.size(); ++f) {
            const Triangle &t = plc.facets[f];
            out << "1 0 " << (f < plc.facetMarkers.size() ? plc.facetMarkers[f] : 0) << '\n';
            out << "3 " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
        }
        out << "# Part 3 - holes: count; each: index, point x y z\n" << plc.holes.size() << '\n';
        for (std::size_t h = 0; h < plc.holes.size(); ++h) {
            out << h + 1;
            for (int k = 0; k < 3; ++k) {
                out << ' ';
                writeDouble(out, plc.holes[h][k]);
            }
            out << '\n';
        }
        out << "# Part 4 - regions: index, seed x y z, attribute, max volume (-1: none)\n";
        out << plc.regions.size() << '\n';
        for (std::size_t r = 0; r < plc.regions.size(); ++r) {
            const PlcRegion &region = plc.regions[r];
            out << r + 1;
            for (int k = 0; k < 3; ++k) {
                out << ' ';
                writeDouble(out, region.seed[k]);
            }
            out << ' ' << region.attribute << " -1\n";
        }
    });
}

} // namespace stratamesh
