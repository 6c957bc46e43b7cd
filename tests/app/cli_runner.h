// Runs the built stratamesh-cli and captures its exit status and both output streams.
#pragma once

#include "support/sanitizer.h"

#include <QProcess>
#include <QString>
#include <QStringList>

#include <algorithm>

namespace stratamesh::test {

struct CliRun {
    bool finished = false; // false: could not start, crashed or timed out
    int exitCode = -1;
    QString out;
    QString err;
};

inline CliRun runCli(const QStringList &arguments, int timeoutMs = 240000)
{
    QProcess process;
    process.start(QStringLiteral(STRATAMESH_CLI_PATH), arguments);
    CliRun run;
    if (!process.waitForStarted(10000))
        return run;
    // The instrumented CLI of a sanitizer build is several times slower (sanitizer.h).
    const bool done = process.waitForFinished(int(std::min(2e9, timeoutMs * kTimeScale)));
    run.finished = done && process.exitStatus() == QProcess::NormalExit;
    if (!done)
        process.kill();
    run.exitCode = process.exitCode();
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

} // namespace stratamesh::test
