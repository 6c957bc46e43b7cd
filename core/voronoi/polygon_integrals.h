// Closed-form integrals over a convex restricted polygon with a density linear on its input
// triangle (thesis eq. 1.3–1.6): ∫ρ, ∫ρ(y − o), ∫ρ|y − o|², by exact formulas for products of
// barycentric coordinates, ∫λ1^a λ2^b λ3^c = 2S·a!b!c!/(a+b+c+2)!.
#pragma once

#include "voronoi/cell_clipper.h"

namespace stratamesh::rvd {

struct PolygonIntegrals {
    double area = 0;
    Vec3 firstMoment = Vec3::Zero(); // ∫ (y − o)
    double mass = 0;                 // ∫ ρ
    Vec3 massMoment = Vec3::Zero();  // ∫ ρ (y − o)
    double energy = 0;               // ∫ ρ |y − o|²

    void add(const PolygonIntegrals &o)
    {
        area += o.area;
        firstMoment += o.firstMoment;
        mass += o.mass;
        massMoment += o.massMoment;
        energy += o.energy;
    }
};

// Integrals of a clipped polygon about its site (ClipVertex positions are relative to it,
// norm2 their squared norms as the clipper sets them); rho holds the density at the input
// triangle's corners, or is null for ρ = 1.
inline PolygonIntegrals integratePolygon(const ClipPolygon &polygon, const double *rho)
{
    PolygonIntegrals r;
    const int n = static_cast<int>(polygon.size());
    if (n < 3)
        return r;
    const Vec3 &x0 = polygon[0].position;
    if (!rho) {
        // ρ = 1: ∫(y − o) = S/3 ΣX, ∫|y − o|² = S/6 (Σ|X|² + Σ_{p<q} X_p·X_q).
        for (int k = 1; k + 1 < n; ++k) {
            const Vec3 &x1 = polygon[k].position, &x2 = polygon[k + 1].position;
            const double s = 0.5 * (x1 - x0).cross(x2 - x0).norm();
            const Vec3 sum = x0 + x1 + x2;
            r.area += s;
            r.firstMoment += s / 3.0 * sum;
            r.energy +=
                s / 12.0
                * (sum.squaredNorm() + polygon[0].norm2 + polygon[k].norm2 + polygon[k + 1].norm2);
        }
        r.mass = r.area;
        r.massMoment = r.firstMoment;
        return r;
    }
    const auto density = [&](const ClipVertex &v) {
        return rho[0] * (1.0 - v.u - v.v) + rho[1] * v.u + rho[2] * v.v;
    };
    const double r0 = density(polygon[0]);
    for (int k = 1; k + 1 < n; ++k) {
        const Vec3 X[3] = {x0, polygon[k].position, polygon[k + 1].position};
        const double p[3] = {r0, density(polygon[k]), density(polygon[k + 1])};
        const double s = 0.5 * (X[1] - X[0]).cross(X[2] - X[0]).norm();
        const Vec3 sum = X[0] + X[1] + X[2];
        const double sq[3] = {polygon[0].norm2, polygon[k].norm2, polygon[k + 1].norm2};
        const double dots[3] = {X[1].dot(X[2]), X[0].dot(X[2]), X[0].dot(X[1])}; // pair opposite m
        r.area += s;
        r.firstMoment += s / 3.0 * sum;
        const double psum = p[0] + p[1] + p[2];
        r.mass += s / 3.0 * psum;
        r.massMoment += s / 12.0 * (p[0] * X[0] + p[1] * X[1] + p[2] * X[2] + psum * sum);
        double e = 0;
        const double sqSum = sq[0] + sq[1] + sq[2];
        for (int m = 0; m < 3; ++m) {
            // 60/S · Σ_{p,q} X_p·X_q ∫λ_m λ_p λ_q
            const double withM = X[m].dot(sum - X[m]);
            const double t = 6 * sq[m] + 2 * (sqSum - sq[m]) + 4 * withM + 2 * dots[m];
            e += p[m] * t;
        }
        r.energy += s / 60.0 * e;
    }
    return r;
}

} // namespace stratamesh::rvd
