// Runs a reader on one file in a forked child, under an address-space cap and a time limit, and
// reports how it ended and how much memory it took: a hostile file must end in a FileError, fast
// and small, and the test process must survive whatever the reader does.
#pragma once

#include "common/error.h"

#include <QDir>
#include <QFile>
#include <QString>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <functional>
#include <new>
#include <string>

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

namespace stratamesh::testing {

struct BoundedRead {
    enum Outcome { Read, FileErrorRaised, OtherError, OutOfMemory, Crashed, TimedOut };
    Outcome outcome = Crashed;
    std::string message; // the FileError's what(), or the other exception's
    long peakKiB = 0;    // growth of the child's resident set while reading
    double seconds = 0;
};

inline const char *outcomeName(BoundedRead::Outcome o)
{
    switch (o) {
    case BoundedRead::Read:
        return "read";
    case BoundedRead::FileErrorRaised:
        return "FileError";
    case BoundedRead::OtherError:
        return "other exception";
    case BoundedRead::OutOfMemory:
        return "out of memory";
    case BoundedRead::Crashed:
        return "crashed";
    case BoundedRead::TimedOut:
        return "timed out";
    }
    return "?";
}

// Extra address space the child may take: far above the 200 MB a small file may cost, far below
// what a dense array sized by a hostile count would ask.
constexpr long boundedReadExtraMiB = 1024;

inline BoundedRead runBounded(const std::function<void()> &reader, int seconds = 20)
{
    int pipeFds[2];
    if (pipe(pipeFds) != 0)
        return {};
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        close(pipeFds[0]);
        long pages = 0;
        if (std::FILE *f = std::fopen("/proc/self/statm", "r")) {
            if (std::fscanf(f, "%ld", &pages) != 1)
                pages = 0;
            std::fclose(f);
        }
        const rlim_t cap =
            rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (rlim_t(boundedReadExtraMiB) << 20);
        const rlimit limit{cap, cap};
        setrlimit(RLIMIT_AS, &limit);
        alarm(unsigned(seconds));
        rusage before{}, after{};
        getrusage(RUSAGE_SELF, &before);
        timeval start{}, end{};
        gettimeofday(&start, nullptr);
        int outcome = BoundedRead::Read;
        std::string message;
        try {
            reader();
        } catch (const FileError &e) {
            outcome = BoundedRead::FileErrorRaised;
            message = e.what();
        } catch (const std::bad_alloc &e) {
            outcome = BoundedRead::OutOfMemory;
            message = e.what();
        } catch (const std::exception &e) {
            outcome = BoundedRead::OtherError;
            message = e.what();
        }
        gettimeofday(&end, nullptr);
        getrusage(RUSAGE_SELF, &after);
        const long peak = after.ru_maxrss - before.ru_maxrss;
        const double elapsed =
            double(end.tv_sec - start.tv_sec) + 1e-6 * double(end.tv_usec - start.tv_usec);
        std::string report = std::to_string(outcome) + "\n" + std::to_string(peak) + "\n"
                             + std::to_string(elapsed) + "\n" + message;
        ssize_t written = write(pipeFds[1], report.data(), report.size());
        (void)written;
        close(pipeFds[1]);
        _exit(0);
    }
    close(pipeFds[1]);
    std::string report;
    char buffer[4096];
    ssize_t n;
    while ((n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0)
        report.append(buffer, std::size_t(n));
    close(pipeFds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    BoundedRead result;
    if (WIFSIGNALED(status)) {
        result.outcome = WTERMSIG(status) == SIGALRM ? BoundedRead::TimedOut : BoundedRead::Crashed;
        result.message = strsignal(WTERMSIG(status));
        return result;
    }
    std::size_t a = report.find('\n'), b = report.find('\n', a + 1), c = report.find('\n', b + 1);
    if (c == std::string::npos)
        return result;
    result.outcome = BoundedRead::Outcome(std::stoi(report.substr(0, a)));
    result.peakKiB = std::stol(report.substr(a + 1, b - a - 1));
    result.seconds = std::stod(report.substr(b + 1, c - b - 1));
    result.message = report.substr(c + 1);
    return result;
}

// Writes `text` as `name` in `dir` and returns its path.
inline std::string writeTestFile(const QString &dir, const QString &name, const QByteArray &text)
{
    const QString path = QDir(dir).filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return {};
    f.write(text);
    return path.toStdString();
}

} // namespace stratamesh::testing
