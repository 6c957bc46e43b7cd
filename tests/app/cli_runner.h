// Runs the built stratamesh-cli and captures its exit status and both output streams.
#pragma once

#include <QProcess>
#include <QString>
#include <QStringList>

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
    const bool done = process.waitForFinished(timeoutMs);
    run.finished = done && process.exitStatus() == QProcess::NormalExit;
    if (!done)
        process.kill();
    run.exitCode = process.exitCode();
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

} // namespace stratamesh::test
