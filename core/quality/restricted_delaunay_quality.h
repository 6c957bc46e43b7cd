// Shape statistics of the restricted Delaunay triangulation (voronoi/restricted_delaunay.h): Q of
// Frey & Borouchaki and angles, as in thesis Table 4.2, to judge a CVT. Here, above voronoi,
// because the triangle measures are this layer's.
#pragma once

#include "voronoi/restricted_delaunay.h"

namespace stratamesh {

struct RestrictedDelaunayQuality {
    int triangles = 0;
    double meanQuality = 0;
    double minQuality = 0;
    double minAngleDeg = 0;
    double percentAngleBelow30 = 0; // triangles with an angle < 30°, in %
};

RestrictedDelaunayQuality restrictedDelaunayQuality(const RestrictedDelaunay &rdt);

} // namespace stratamesh
