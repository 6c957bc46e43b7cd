// Progress and cancel as a core service: long algorithms report here and stop by exception.
//
// A Progress is a root (it holds the cancel flag and the callback) or a sub-task of another
// Progress: a stage name and a share [from, to] of the parent's range, so that a nested stage
// reports its own 0..1 and never needs to know where it sits in the whole run (the model is
// Geogram's ProgressTask). The root only ever reports a fraction that moves forward, whatever
// order the stages tick in, and a cancel raises Cancelled at the next tick of any sub-task.
//
// Thread-safety: tick() and isCancelled() may be called from TBB worker threads at the same
// time; the root serialises its callback. Creating or destroying a sub-task is not concurrent
// with its own ticks (a sub-task lives on the stack of the stage it measures).
#pragma once

#include "common/error.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <mutex>
#include <string>
#include <vector>

namespace stratamesh {

class Progress {
public:
    // fraction in [0, 1] of the whole run, never decreasing; stage is the chain of stage names
    // from the root's first sub-task down to the one that ticked, joined by ": ".
    using Callback = std::function<void(double fraction, const std::string &stage)>;

    Progress() = default;
    explicit Progress(Callback callback) : m_callback(std::move(callback)) {}
    // A sub-task covering [from, to] of `parent`'s own 0..1; `name` prefixes its stages.
    Progress(Progress &parent, double from, double to, std::string name = {})
        : m_parent(&parent), m_root(parent.m_root ? parent.m_root : &parent),
          m_from(std::clamp(from, 0.0, 1.0)), m_to(std::clamp(to, m_from, 1.0)),
          m_name(std::move(name))
    {
    }
    Progress(const Progress &) = delete;
    Progress &operator=(const Progress &) = delete;

    // Stops the whole run (a sub-task's cancel is its root's).
    void cancel() { root().m_cancelled.store(true); }
    bool isCancelled() const { return root().m_cancelled.load(); }
    // Throws Cancelled if a stop was requested; for loops that check more often than they report.
    void checkCancel() const
    {
        if (isCancelled())
            throw Cancelled();
    }

    // Reports this task's own fraction in [0, 1] and throws Cancelled if a stop was requested;
    // call between units of work.
    void tick(double fraction, const std::string &stage = {})
    {
        checkCancel();
        if (m_parent)
            m_parent->tick(m_from + (m_to - m_from) * std::clamp(fraction, 0.0, 1.0),
                           joined(stage));
        else
            report(fraction, stage);
    }

    // The last fraction the root reported (0 before any tick).
    double reported() const
    {
        const Progress &r = root();
        std::lock_guard<std::mutex> lock(r.m_mutex);
        return r.m_last;
    }

    // A shared "no progress wanted" instance for callers that do not care.
    static Progress &none()
    {
        thread_local Progress p;
        return p;
    }

private:
    const Progress &root() const { return m_root ? *m_root : *this; }
    Progress &root() { return m_root ? *m_root : *this; }

    std::string joined(const std::string &stage) const
    {
        if (m_name.empty())
            return stage;
        return stage.empty() ? m_name : m_name + ": " + stage;
    }

    void report(double fraction, const std::string &stage)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_last = std::max(m_last, std::clamp(fraction, 0.0, 1.0));
        if (m_callback)
            m_callback(m_last, stage);
    }

    Progress *m_parent = nullptr;
    Progress *m_root = nullptr;
    double m_from = 0.0;
    double m_to = 1.0;
    std::string m_name;
    Callback m_callback;
    std::atomic<bool> m_cancelled{false};
    mutable std::mutex m_mutex;
    double m_last = 0.0;
};

// The first `levels` names of a stage chain ("Refinement round 2: CVT: iteration 3" at 2 levels is
// "Refinement round 2: CVT"), for grouping reports by stage.
inline std::string stagePrefix(const std::string &stage, int levels)
{
    std::size_t end = 0;
    for (int level = 0; level < levels; ++level) {
        end = stage.find(": ", level == 0 ? 0 : end + 2);
        if (end == std::string::npos)
            return stage;
    }
    return stage.substr(0, end);
}

// A part of a caller's progress bar: fractions [0, 1] reported here land in [from, to] of the
// parent, and the parent's cancel stops the part at its next tick.
inline Progress progressRange(Progress &parent, double from, double to)
{
    return Progress(parent, from, to);
}

// A stage made of a known sequence of steps, each a share of the stage's range: step(i, name)
// gives the sub-task of step i, whose stages read "name (i+1/n)". Shares are relative weights
// (e.g. measured times); the stage's range is split in proportion.
class ProgressSteps {
public:
    ProgressSteps(Progress &parent, std::initializer_list<double> weights)
        : m_parent(parent), m_bounds{0.0}
    {
        double total = 0.0;
        for (double w : weights)
            total += std::max(w, 0.0);
        double sum = 0.0;
        for (double w : weights) {
            sum += std::max(w, 0.0);
            m_bounds.push_back(total > 0.0 ? sum / total : 1.0);
        }
    }
    int count() const { return static_cast<int>(m_bounds.size()) - 1; }
    // Step i's sub-task; ticks its start.
    Progress step(int i, const std::string &name)
    {
        const int n = count();
        const int k = std::clamp(i, 0, n - 1);
        m_parent.tick(m_bounds[k], label(k, name));
        return Progress(m_parent, m_bounds[k], m_bounds[k + 1], label(k, name));
    }

private:
    std::string label(int k, const std::string &name) const
    {
        return name + " (" + std::to_string(k + 1) + "/" + std::to_string(count()) + ")";
    }

    Progress &m_parent;
    std::vector<double> m_bounds;
};

// Counts units of work done by a loop, possibly in parallel, and ticks every `every` units
// (and throws Cancelled there); one atomic add per call otherwise.
class ProgressCounter {
public:
    ProgressCounter(Progress &progress, std::size_t total, std::size_t every,
                    std::string stage = {})
        : m_progress(progress), m_total(std::max<std::size_t>(total, 1)),
          m_every(std::max<std::size_t>(every, 1)), m_stage(std::move(stage))
    {
    }
    void add(std::size_t units = 1)
    {
        const std::size_t before = m_done.fetch_add(units);
        if ((before + units) / m_every != before / m_every)
            m_progress.tick(static_cast<double>(before + units) / m_total, m_stage);
    }

private:
    Progress &m_progress;
    std::size_t m_total;
    std::size_t m_every;
    std::string m_stage;
    std::atomic<std::size_t> m_done{0};
};

} // namespace stratamesh
