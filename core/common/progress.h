// Progress and cancel as a core service: long algorithms report here and stop by exception.
#pragma once

#include "common/error.h"

#include <atomic>
#include <functional>
#include <string>

namespace stratamesh {

class Progress {
public:
    // fraction in [0, 1]; the callback may be called from worker threads only through tick().
    using Callback = std::function<void(double fraction, const std::string &stage)>;

    Progress() = default;
    explicit Progress(Callback callback) : m_callback(std::move(callback)) {}

    void cancel() { m_cancelled.store(true); }
    bool isCancelled() const { return m_cancelled.load(); }

    // Reports and throws Cancelled if a stop was requested; call between units of work.
    void tick(double fraction, const std::string &stage = {})
    {
        if (m_cancelled.load())
            throw Cancelled();
        if (m_callback)
            m_callback(fraction, stage);
    }

    // A shared "no progress wanted" instance for callers that do not care.
    static Progress &none()
    {
        thread_local Progress p;
        return p;
    }

private:
    Callback m_callback;
    std::atomic<bool> m_cancelled{false};
};

} // namespace stratamesh
