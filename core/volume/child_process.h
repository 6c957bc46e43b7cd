// A child process with a wall-clock limit, an address-space limit and kill on cancel: how
// StrataMesh runs code that may take its host down (TetGen, formats.md §4.5). POSIX only, no Qt.
#pragma once

#include "common/progress.h"

#include <functional>
#include <string>
#include <vector>

namespace stratamesh {

struct ChildLimits {
    double timeLimitSeconds = 0.0; // wall clock; 0 = none
    double memoryLimitMB = 0.0;    // RLIMIT_AS of the child; 0 = none
};

struct ChildExit {
    enum class Kind {
        Exited,     // exitCode is set
        Signalled,  // ended by a signal we did not send (crash, or killed from outside)
        TimedOut,   // we killed it at the time limit
        Cancelled,  // we killed it because progress was cancelled
        SpawnFailed // could not start: message says why
    };
    Kind kind = Kind::SpawnFailed;
    int exitCode = -1;
    int signal = 0;
    double seconds = 0.0;
    std::string message;
};

// Runs argv[0] (a path, no PATH search) with stdout and stderr appended to logPath, in a process
// group of its own that dies with the calling thread (PR_SET_PDEATHSIG). Polls every 10 ms and
// reports progress.tick(elapsed / limit, stage) about every 0.2 s; on a cancel or at the time limit
// kills the whole group with SIGKILL and reaps it before returning. Never throws for the child's
// failures; onStarted (may be empty) receives the child's pid.
ChildExit runChild(const std::vector<std::string> &argv, const std::string &logPath,
                   const ChildLimits &limits, Progress &progress, const std::string &stage,
                   const std::function<void(int pid)> &onStarted = {});

// The last non-empty lines of a text file (at most `count`, read from its last 64 KiB).
std::vector<std::string> lastLines(const std::string &path, std::size_t count);

} // namespace stratamesh
