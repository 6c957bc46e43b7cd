#include "cvt/cvt_optimizer.h"

#include "common/error.h"
#include "cvt/cvt_energy.h"
#include "cvt/site_relocation.h"
#include "params/param_tables.h"

#include <LBFGS.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

namespace stratamesh {
namespace {

using Vector = Eigen::VectorXd;

// Raised from the iteration hook to leave LBFGSpp once a stop criterion holds.
struct StopOptimization {
    std::string reason;
};

// Raised from the iteration hook when an accepted iterate has sites without a cell.
struct LostSites {};

// Carries an error of our own evaluation through LBFGSpp, which reports its own failures with
// std::logic_error / std::runtime_error: those end the run, ours must reach the caller.
struct EvaluationFailure {
    std::exception_ptr error;
};

std::string iterationStage(int k, int n, double f, double g)
{
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "CVT iteration %d/%d: F = %.6g, |grad F| = %.3g", k, n, f,
                  g);
    return buffer;
}

// Sites are optimised in normalised coordinates x = (s − c)/L around the bounding box centre,
// so that L-BFGS differences keep their digits on georeferenced models. L = √area/10: LBFGSpp's
// first step moves the sites by a total length of one unit, a tenth of the typical spacing per
// site; later steps are scale-free.
class Objective {
public:
    Objective(const RestrictionDomain &domain, const CvtParams &params, Progress &progress,
              CvtResult &result)
        : m_domain(domain), m_params(params), m_progress(progress), m_result(result)
    {
        Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
        for (const Vec3 &p : domain.points) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        m_center = domain.points.empty() ? Vec3::Zero() : Vec3(0.5 * (lo + hi));
        const double area = domain.surfaceArea();
        m_scale = area > 0                ? 0.1 * std::sqrt(area)
                  : domain.points.empty() ? 1.0
                                          : std::max((hi - lo).norm(), 1e-300);
    }

    Vector toX(const std::vector<Vec3> &sites) const
    {
        Vector x(3 * sites.size());
        for (std::size_t i = 0; i < sites.size(); ++i)
            x.segment<3>(3 * i) = (sites[i] - m_center) / m_scale;
        return x;
    }
    std::vector<Vec3> toSites(const Vector &x) const
    {
        std::vector<Vec3> s(x.size() / 3);
        for (std::size_t i = 0; i < s.size(); ++i)
            s[i] = m_center + m_scale * Vec3(x.segment<3>(3 * i));
        return s;
    }

    const CvtEvaluation &evaluate(const std::vector<Vec3> &sites)
    {
        m_progress.tick(m_fraction, m_stage); // a cancel request is honoured between evaluations
        m_last = evaluateCvtEnergy(m_domain, sites, m_params.alpha, m_workspace,
                                   m_params.neighbourSearch);
        ++m_result.evaluations;
        m_result.rvdSeconds += m_last.rvdSeconds;
        m_result.delaunaySeconds += m_last.delaunaySeconds;
        m_result.neighbourSearches = m_workspace.neighbourReuse.searches;
        return m_last;
    }

    const CvtEvaluation &last() const { return m_last; }
    bool fixed(std::size_t i) const
    {
        return i < m_params.fixedSites.size() && m_params.fixedSites[i] != 0;
    }

    static int emptyCells(const CvtEvaluation &e)
    {
        int n = 0;
        for (double m : e.cells.mass)
            n += !(m > 0);
        return n;
    }

    // LBFGSpp interface.
    double operator()(const Vector &x, Vector &grad)
    {
        try {
            evaluate(toSites(x));
        } catch (...) {
            throw EvaluationFailure{std::current_exception()};
        }
        const CvtEvaluation &e = m_last;
        grad.resize(x.size());
        for (std::size_t i = 0; i < e.gradient.size(); ++i)
            grad.segment<3>(3 * i) = fixed(i) ? Vec3::Zero().eval() : Vec3(m_scale * e.gradient[i]);
        return e.energy;
    }

    // Called once per accepted iteration (after the line search), with F and ∇F at the new x.
    void onIteration(double fx, const Vector &x, const Vector &grad)
    {
        record(fx, grad.norm() / m_scale);
        m_best = x;
        if (m_params.gradientTolerance > 0
            && m_result.gradientNorm.back() <= m_params.gradientTolerance)
            throw StopOptimization{"gradient"};
        if (emptyCells(m_last) > 0)
            throw LostSites{}; // m_last is the accepted iterate: the line search ends on it
        if (m_result.iterations >= m_params.iterations)
            throw StopOptimization{"iterations"};
    }

    // Puts the sites with an empty cell back on the model; the L-BFGS history is then restarted.
    Vector relocate(const Vector &x)
    {
        std::vector<Vec3> sites = toSites(x);
        evaluate(sites); // the owners and masses of exactly these sites
        m_result.relocatedSites +=
            relocateLostSites(m_domain, m_last.cells, m_workspace.pointOwners, sites);
        return toX(sites);
    }

    CellIntegralsWorkspace &workspace() { return m_workspace; }
    const RestrictionDomain &domain() const { return m_domain; }

    void record(double energy, double gradientNorm)
    {
        const int k = static_cast<int>(m_result.energy.size()) + 1;
        m_result.energy.push_back(energy);
        m_result.gradientNorm.push_back(gradientNorm);
        m_result.iterations = k;
        if (m_params.onIteration)
            m_params.onIteration({k, energy, gradientNorm});
        m_fraction = static_cast<double>(k) / std::max(1, m_params.iterations);
        m_stage = iterationStage(k, m_params.iterations, energy, gradientNorm);
        m_progress.tick(m_fraction, m_stage);
    }

    Vector m_best;

private:
    const RestrictionDomain &m_domain;
    const CvtParams &m_params;
    Progress &m_progress;
    CvtResult &m_result;
    CellIntegralsWorkspace m_workspace;
    CvtEvaluation m_last;
    Vec3 m_center;
    double m_scale = 1;
    double m_fraction = 0;
    std::string m_stage = "CVT";
};

// LBFGSpp calls its line search once per iteration, which gives our iteration hook. The search
// itself is a bisection on the weak Wolfe conditions (Lewis & Overton 2013, "Nonsmooth
// optimization via quasi-Newton methods"): no interpolation, so kinks of the piecewise-smooth
// energy do not mislead it, and its curvature condition keeps s·y > 0 for the L-BFGS update.
template <class Scalar>
class HookedLineSearch {
public:
    template <class Foo>
    static void LineSearch(Foo &f, Scalar &fx, Vector &x, Vector &grad, Scalar &step,
                           const Vector &drt, const Vector &xp,
                           const LBFGSpp::LBFGSParam<Scalar> &param)
    {
        const Scalar f0 = fx;
        const Scalar dg0 = grad.dot(drt);
        if (!(dg0 < 0))
            throw std::logic_error("the search direction does not decrease the energy");
        Scalar lo = 0, hi = std::numeric_limits<Scalar>::infinity(), t = step;
        for (int k = 0; k < param.max_linesearch; ++k) {
            x.noalias() = xp + t * drt;
            const Scalar ft = f(x, grad);
            if (!std::isfinite(ft) || ft > f0 + param.ftol * t * dg0) {
                hi = t;
            } else if (grad.dot(drt) < param.wolfe * dg0) {
                lo = t; // sufficient decrease, but the slope is still steep: go farther
            } else {
                fx = ft;
                step = t;
                f.onIteration(fx, x, grad);
                return;
            }
            t = std::isfinite(hi) ? 0.5 * (lo + hi) : 2 * t;
        }
        if (!(lo > 0))
            throw std::runtime_error("the line search found no decrease");
        // Out of trials with a decrease in hand: take it (its curvature is unproven).
        x.noalias() = xp + lo * drt;
        fx = f(x, grad);
        step = lo;
        f.onIteration(fx, x, grad);
    }
};

void runLbfgs(Objective &objective, const std::vector<Vec3> &initial, const CvtParams &params,
              CvtResult &result)
{
    LBFGSpp::LBFGSParam<double> p;
    p.m = std::max(1, params.lbfgsMemory);
    p.epsilon = 0; // stopping is decided by our hook
    p.epsilon_rel = 0;
    p.past = 0;
    p.max_iterations = 0;
    p.max_linesearch = 40;
    p.wolfe = 0.9;
    Vector x = objective.toX(initial);
    objective.m_best = x;
    double fx = 0;
    // The first evaluation of minimize() is the initial point.
    struct Wrapper {
        Objective &o;
        CvtResult &r;
        bool first = true;
        double operator()(const Vector &x, Vector &g)
        {
            const double f = o(x, g);
            if (first) {
                r.initialEnergy = f;
                r.initialGradientNorm = o.last().gradientNorm();
                first = false;
            }
            return f;
        }
        void onIteration(double fx, const Vector &x, const Vector &g) { o.onIteration(fx, x, g); }
    } wrapper{objective, result};
    result.stopReason = "gradient";
    for (;;) {
        LBFGSpp::LBFGSSolver<double, HookedLineSearch> solver(p);
        try {
            solver.minimize(wrapper, x, fx);
        } catch (const EvaluationFailure &failure) {
            std::rethrow_exception(failure.error);
        } catch (const Cancelled &) {
            throw; // from the progress tick of the iteration hook
        } catch (const LostSites &) {
            // Relocate, then restart L-BFGS from there with a fresh history.
            x = objective.relocate(objective.m_best);
            objective.m_best = x;
            if (result.iterations < params.iterations)
                continue;
            result.stopReason = "iterations";
        } catch (const StopOptimization &stop) {
            result.stopReason = stop.reason;
        } catch (const std::logic_error &) {
            result.stopReason = "no descent"; // L-BFGS direction not a descent direction
        } catch (const std::runtime_error &) {
            result.stopReason = "line search"; // no sufficient decrease: at a (numerical) minimum
        }
        break;
    }
    result.sites = objective.toSites(objective.m_best);
}

void runLloyd(Objective &objective, const std::vector<Vec3> &initial, const CvtParams &params,
              CvtResult &result)
{
    std::vector<Vec3> sites = initial;
    CvtEvaluation e = objective.evaluate(sites);
    result.initialEnergy = e.energy;
    result.initialGradientNorm = e.gradientNorm();
    result.stopReason = "iterations";
    for (int k = 1; k <= params.iterations; ++k) {
        for (std::size_t i = 0; i < sites.size(); ++i)
            if (e.cells.mass[i] > 0 && !objective.fixed(i))
                sites[i] += e.cells.moment[i] / e.cells.mass[i]; // to the centroid g_i
        e = objective.evaluate(sites);
        if (Objective::emptyCells(e) > 0) {
            result.relocatedSites += relocateLostSites(objective.domain(), e.cells,
                                                       objective.workspace().pointOwners, sites);
            e = objective.evaluate(sites);
        }
        objective.record(e.energy, e.gradientNorm());
        if (params.gradientTolerance > 0 && e.gradientNorm() <= params.gradientTolerance) {
            result.stopReason = "gradient";
            break;
        }
    }
    result.sites = sites;
}

} // namespace

CvtResult optimizeCvt(const RestrictionDomain &domain, const std::vector<Vec3> &initialSites,
                      const CvtParams &params, Progress &progress)
{
    if (initialSites.empty())
        throw InputError("CVT: no sites to optimise");
    checkParams(cvtParamTable(), params);
    if (params.lloyd && params.alpha > 0)
        throw InputError("CVT: Lloyd iterations minimise F_CVT only; alpha > 0 needs L-BFGS");
    if (params.threads < 0)
        throw InputError("CVT: the number of threads must not be negative");

    const auto start = std::chrono::steady_clock::now();
    CvtResult result;
    tbb::task_arena arena(params.threads > 0 ? params.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        result.threads = tbb::this_task_arena::max_concurrency();
        Objective objective(domain, params, progress, result);
        if (params.iterations == 0) {
            const CvtEvaluation e = objective.evaluate(initialSites);
            result.initialEnergy = e.energy;
            result.initialGradientNorm = e.gradientNorm();
            result.sites = initialSites;
            result.stopReason = "iterations";
        } else if (params.lloyd) {
            runLloyd(objective, initialSites, params, result);
        } else {
            runLbfgs(objective, initialSites, params, result);
        }
    });
    result.totalSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace stratamesh
