#include "volume/child_process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace stratamesh {

namespace {

void killGroup(pid_t pid)
{
    ::kill(-pid, SIGKILL);
    ::kill(pid, SIGKILL);
}

// Only async-signal-safe calls between fork and exec: the parent may have other threads.
[[noreturn]] void execChild(char *const *argv, const char *logPath, rlim_t memoryBytes,
                            rlim_t cpuSeconds, int errorPipe)
{
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int log = ::open(logPath, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0600);
    const int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (log >= 0) {
        ::dup2(log, STDOUT_FILENO);
        ::dup2(log, STDERR_FILENO);
    }
    if (null >= 0)
        ::dup2(null, STDIN_FILENO);
    if (memoryBytes > 0) {
        const rlimit limit{memoryBytes, memoryBytes};
        ::setrlimit(RLIMIT_AS, &limit);
    }
    if (cpuSeconds > 0) {
        const rlimit limit{cpuSeconds, cpuSeconds};
        ::setrlimit(RLIMIT_CPU, &limit);
    }
    ::execv(argv[0], argv);
    const int error = errno;
    [[maybe_unused]] const ssize_t written = ::write(errorPipe, &error, sizeof error);
    ::_exit(127);
}

} // namespace

ChildExit runChild(const std::vector<std::string> &argv, const std::string &logPath,
                   const ChildLimits &limits, Progress &progress, const std::string &stage,
                   const std::function<void(int pid)> &onStarted)
{
    ChildExit result;
    if (argv.empty()) {
        result.message = "no program to run";
        return result;
    }
    std::vector<std::vector<char>> storage;
    std::vector<char *> args;
    for (const std::string &a : argv)
        storage.emplace_back(a.c_str(), a.c_str() + a.size() + 1);
    for (std::vector<char> &a : storage)
        args.push_back(a.data());
    args.push_back(nullptr);
    const rlim_t memoryBytes =
        limits.memoryLimitMB > 0 ? static_cast<rlim_t>(limits.memoryLimitMB * 1024.0 * 1024.0) : 0;
    // A CPU backstop in case the wall-clock watch below never runs (the parent is stopped).
    const rlim_t cpuSeconds =
        limits.timeLimitSeconds > 0 ? static_cast<rlim_t>(2.0 * limits.timeLimitSeconds + 10.0) : 0;

    int errorPipe[2];
    if (::pipe2(errorPipe, O_CLOEXEC) != 0) {
        result.message = std::string("cannot create a pipe: ") + std::strerror(errno);
        return result;
    }
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        result.message = std::string("cannot fork: ") + std::strerror(errno);
        ::close(errorPipe[0]);
        ::close(errorPipe[1]);
        return result;
    }
    if (pid == 0)
        execChild(args.data(), logPath.c_str(), memoryBytes, cpuSeconds, errorPipe[1]);
    ::setpgid(pid, pid); // also in the child: whichever runs first
    ::close(errorPipe[1]);
    int execError = 0;
    const bool execFailed = ::read(errorPipe[0], &execError, sizeof execError) == sizeof execError;
    ::close(errorPipe[0]);
    if (execFailed) {
        int status;
        ::waitpid(pid, &status, 0);
        result.message = "cannot run " + argv[0] + ": " + std::strerror(execError);
        return result;
    }
    if (onStarted)
        onStarted(static_cast<int>(pid));

    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    double lastTick = 0.0;
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid)
            break;
        if (done < 0 && errno != EINTR) {
            killGroup(pid);
            result.message = std::string("lost the child process: ") + std::strerror(errno);
            return result;
        }
        bool cancelled = progress.isCancelled();
        const double t = elapsed();
        if (!cancelled && t - lastTick > 0.2) {
            lastTick = t;
            try {
                progress.tick(
                    limits.timeLimitSeconds > 0 ? std::min(1.0, t / limits.timeLimitSeconds) : 0.5,
                    stage);
            } catch (const Cancelled &) {
                cancelled = true;
            }
        }
        const bool timedOut = limits.timeLimitSeconds > 0 && t > limits.timeLimitSeconds;
        if (cancelled || timedOut) {
            killGroup(pid);
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            result.kind = cancelled ? ChildExit::Kind::Cancelled : ChildExit::Kind::TimedOut;
            result.seconds = elapsed();
            return result;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    result.seconds = elapsed();
    // A crashed helper may leave grandchildren; none should outlive it.
    ::kill(-pid, SIGKILL);
    if (WIFEXITED(status)) {
        result.kind = ChildExit::Kind::Exited;
        result.exitCode = WEXITSTATUS(status);
    } else {
        result.kind = ChildExit::Kind::Signalled;
        result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    }
    return result;
}

std::vector<std::string> lastLines(const std::string &path, std::size_t count)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return {};
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    const std::streamoff from = size > 65536 ? size - 65536 : 0;
    in.seekg(from);
    std::string text(static_cast<std::size_t>(size - from), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    std::vector<std::string> lines;
    std::size_t end = text.size();
    while (end > 0 && lines.size() < count) {
        const std::size_t begin = text.rfind('\n', end - 1);
        const std::size_t first = begin == std::string::npos ? 0 : begin + 1;
        std::string line = text.substr(first, end - first);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
        const std::size_t lead = line.find_first_not_of(' ');
        if (lead != std::string::npos)
            lines.insert(lines.begin(), line.substr(lead));
        if (begin == std::string::npos)
            break;
        end = begin;
    }
    return lines;
}

} // namespace stratamesh
