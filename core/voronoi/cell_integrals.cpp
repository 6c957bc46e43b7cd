#include "voronoi/cell_integrals.h"

#include "voronoi/cell_clipper.h"
#include "voronoi/polygon_integrals.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <mutex>

namespace stratamesh {
namespace {

constexpr int kPointChunk = 1024;
constexpr int kTriangleChunk = 256;
constexpr int kSegmentChunk = 256;

using detail::LineRecord;
using detail::SurfaceRecord;

int chunkCount(std::size_t n, int chunk)
{
    return static_cast<int>((n + chunk - 1) / chunk);
}

// Folds the records of each chunk into the per-site sums in chunk order while later chunks are
// still being clipped (a serial fold after the loop left one thread idle): the thread that
// finishes a chunk folds every finished chunk next in order. The additions per site come in the
// same order as in a serial fold, so the sums are bit-identical.
class OrderedFold {
public:
    explicit OrderedFold(int chunks) : m_done(chunks, 0) {}
    template <class Fold>
    void finished(int chunk, Fold &&fold)
    {
        const std::lock_guard<std::mutex> lock(m_mutex);
        m_done[chunk] = 1;
        while (m_next < static_cast<int>(m_done.size()) && m_done[m_next])
            fold(m_next++);
    }

private:
    std::mutex m_mutex;
    std::vector<char> m_done;
    int m_next = 0;
};

// F_B of one piece C1C2 of cell p (thesis Fig 4.2) and its gradient. A piece end lying on
// bisector(p, o) moves along its segment (direction d) when p or o moves:
// dC = d·[(p_o − C)·dp_o + (C − p)·dp] / ((p_o − p)·d).
void boundaryPiece(const std::vector<Vec3> &sites, int p, const rvd::SegmentEnd &c1,
                   const rvd::SegmentEnd &c2, const Vec3 &d, std::vector<LineRecord> &out)
{
    const Vec3 &sp = sites[p];
    const Vec3 a = c1.position - sp, b = c2.position - sp;
    const Vec3 n = a.cross(b);
    LineRecord self{p, (c2.position - c1.position).norm(), 0.5 * n.squaredNorm(),
                    n.cross(c2.position - c1.position)};
    const Vec3 g1 = b.cross(n); // ∂F/∂C1
    const Vec3 g2 = n.cross(a); // ∂F/∂C2
    const rvd::SegmentEnd *ends[2] = {&c1, &c2};
    const Vec3 *grads[2] = {&g1, &g2};
    for (int e = 0; e < 2; ++e) {
        const int o = ends[e]->site;
        if (o < 0)
            continue;
        const Vec3 &so = sites[o];
        const double den = (so - sp).dot(d);
        if (den == 0)
            continue;
        const double factor = d.dot(*grads[e]) / den;
        self.gradient += factor * (ends[e]->position - sp);
        out.push_back({o, 0, 0, factor * (so - ends[e]->position)});
    }
    out.push_back(self);
}

} // namespace

double CellIntegrals::totalEnergy() const
{
    double e = 0;
    for (double x : energy)
        e += x;
    return e;
}

void computePointOwners(const RestrictionDomain &domain, const VoronoiNeighbours &delaunay,
                        CellIntegralsWorkspace &workspace)
{
    const int np = static_cast<int>(domain.points.size());
    const bool hints = workspace.siteCount == delaunay.siteCount()
                       && static_cast<int>(workspace.pointOwners.size()) == np;
    if (!hints)
        workspace.pointOwners.assign(np, -1);
    workspace.siteCount = delaunay.siteCount();
    tbb::parallel_for(tbb::blocked_range<int>(0, chunkCount(np, kPointChunk), 1),
                      [&](const tbb::blocked_range<int> &r) {
                          for (int c = r.begin(); c < r.end(); ++c) {
                              int previous = -1;
                              const int end = std::min(np, (c + 1) * kPointChunk);
                              for (int p = c * kPointChunk; p < end; ++p) {
                                  const int hint = workspace.pointOwners[p] >= 0
                                                       ? workspace.pointOwners[p]
                                                       : previous;
                                  previous = workspace.pointOwners[p] =
                                      delaunay.owner(domain.points[p], hint);
                              }
                          }
                      });
}

CellIntegrals integrateCells(const RestrictionDomain &domain, const VoronoiNeighbours &delaunay,
                             const CellIntegralsOptions &options, CellIntegralsWorkspace &workspace)
{
    const int ns = delaunay.siteCount();
    CellIntegrals result;
    result.mass.assign(ns, 0.0);
    result.moment.assign(ns, Vec3::Zero());
    result.energy.assign(ns, 0.0);
    result.area.assign(ns, 0.0);
    result.length.assign(ns, 0.0);
    result.boundaryGradient.assign(ns, Vec3::Zero());
    if (ns == 0)
        return result;
    computePointOwners(domain, delaunay, workspace);
    const std::vector<int> &owners = workspace.pointOwners;
    const std::vector<Vec3> &sites = delaunay.sites();

    const int nt = static_cast<int>(domain.triangles.size());
    std::vector<std::vector<SurfaceRecord>> &surfaceRecords = workspace.surfaceRecords;
    surfaceRecords.resize(chunkCount(nt, kTriangleChunk));
    OrderedFold surfaceFold(static_cast<int>(surfaceRecords.size()));
    // One clipper per thread for the whole loop (not per task): its marks and its answers about
    // sites beyond the lists stay warm from one task to the next.
    tbb::enumerable_thread_specific<rvd::CellClipper> clippers(
        [&] { return rvd::CellClipper(domain, delaunay); });
    const auto foldSurface = [&](int c) {
        for (const SurfaceRecord &rec : surfaceRecords[c]) {
            result.area[rec.site] += rec.area;
            result.mass[rec.site] += rec.mass;
            result.energy[rec.site] += rec.energy;
            result.moment[rec.site] += rec.moment;
        }
    };
    tbb::parallel_for(
        tbb::blocked_range<int>(0, static_cast<int>(surfaceRecords.size()), 1),
        [&](const tbb::blocked_range<int> &r) {
            rvd::CellClipper &clipper = clippers.local();
            for (int c = r.begin(); c < r.end(); ++c) {
                std::vector<SurfaceRecord> &out = surfaceRecords[c];
                out.clear();
                const int end = std::min(nt, (c + 1) * kTriangleChunk);
                for (int t = c * kTriangleChunk; t < end; ++t) {
                    const Triangle &tri = domain.triangles[t];
                    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
                        continue; // no area, and its edges are not edges
                    const int own[3] = {owners[tri[0]], owners[tri[1]], owners[tri[2]]};
                    double rho[3];
                    if (!domain.density.empty())
                        for (int k = 0; k < 3; ++k)
                            rho[k] = domain.density[tri[k]];
                    clipper.forEachTrianglePart(
                        t, own, [&](int site, const rvd::ClipPolygon &polygon) {
                            const rvd::PolygonIntegrals in = rvd::integratePolygon(
                                polygon, domain.density.empty() ? nullptr : rho);
                            if (!out.empty() && out.back().site == site) {
                                SurfaceRecord &b = out.back();
                                b.area += in.area;
                                b.mass += in.mass;
                                b.energy += in.energy;
                                b.moment += in.massMoment;
                            } else {
                                out.push_back({site, in.area, in.mass, in.energy, in.massMoment});
                            }
                        });
                }
                surfaceFold.finished(c, foldSurface);
            }
        });

    if (!options.boundary)
        return result;
    const int nseg = static_cast<int>(domain.segments.size());
    std::vector<std::vector<LineRecord>> &lineRecords = workspace.lineRecords;
    lineRecords.resize(chunkCount(nseg, kSegmentChunk));
    tbb::parallel_for(
        tbb::blocked_range<int>(0, static_cast<int>(lineRecords.size()), 1),
        [&](const tbb::blocked_range<int> &r) {
            rvd::CellClipper clipper(domain, delaunay);
            for (int c = r.begin(); c < r.end(); ++c) {
                std::vector<LineRecord> &out = lineRecords[c];
                out.clear();
                const int end = std::min(nseg, (c + 1) * kSegmentChunk);
                for (int s = c * kSegmentChunk; s < end; ++s) {
                    const auto &seg = domain.segments[s];
                    if (seg[0] == seg[1])
                        continue;
                    const Vec3 d = domain.points[seg[1]] - domain.points[seg[0]];
                    const int own[2] = {owners[seg[0]], owners[seg[1]]};
                    clipper.forEachSegmentPart(
                        s, own, [&](int site, const rvd::SegmentEnd &a, const rvd::SegmentEnd &b) {
                            boundaryPiece(sites, site, a, b, d, out);
                        });
                }
            }
        });
    for (const auto &records : lineRecords)
        for (const LineRecord &rec : records) {
            result.length[rec.site] += rec.length;
            result.boundaryEnergy += rec.energy;
            result.boundaryGradient[rec.site] += rec.gradient;
        }
    return result;
}

} // namespace stratamesh
