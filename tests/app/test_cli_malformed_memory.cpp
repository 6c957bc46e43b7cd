// Peak memory of stratamesh-cli on hostile files (issue 18): every malformed file under 1 KB of
// the committed corpus (tests/fuzz/regressions: the inputs the fuzzers and the reader tests found
// hostile) is given to `info` and to `convert`, each in a child process of its own, whose peak
// resident set (wait4's rusage, that child's alone) must stay under 200 MB; the run must end in
// a clear error naming the file, within 20 s, and convert must leave no output behind.
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <cerrno>
#include <csignal>
#include <ctime>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace {

struct ChildRun {
    bool started = false;
    bool timedOut = false;
    int status = 0;   // as from wait4
    long peakKiB = 0; // ru_maxrss of this child alone
    std::string err;  // its standard error
};

// Runs the CLI with `arguments`, reading its stderr until it closes, then reaps it with wait4.
ChildRun runChild(const QStringList &arguments, int seconds)
{
    ChildRun run;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0)
        return run;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    std::vector<std::string> args{STRATAMESH_CLI_PATH};
    for (const QString &a : arguments)
        args.push_back(a.toStdString());
    std::vector<char *> argv;
    for (std::string &a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (spawned != 0) {
        close(fds[0]);
        return run;
    }
    run.started = true;
    const std::time_t deadline = std::time(nullptr) + seconds;
    char buffer[4096];
    for (;;) {
        pollfd p{fds[0], POLLIN, 0};
        const int left = int(deadline - std::time(nullptr));
        if (left <= 0) {
            run.timedOut = true;
            kill(pid, SIGKILL);
            break;
        }
        const int ready = poll(&p, 1, left * 1000);
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0)
            continue; // the deadline is checked above
        const ssize_t n = read(fds[0], buffer, sizeof buffer);
        if (n <= 0)
            break;
        run.err.append(buffer, std::size_t(n));
    }
    close(fds[0]);
    rusage usage{};
    while (wait4(pid, &run.status, 0, &usage) < 0 && errno == EINTR) {
    }
    run.peakKiB = usage.ru_maxrss;
    return run;
}

// Under AddressSanitizer every allocation carries redzones and a quarantine: the bound is the
// same 200 MB above what the tool needs to start, measured on an empty command.
long baselineKiB()
{
#if defined(STRATAMESH_SANITIZED)
    static const long base = runChild({"--version"}, 60).peakKiB;
    return base;
#else
    return 0;
#endif
}

constexpr long limitKiB = 200 * 1024;

} // namespace

class TestCliMalformedMemory : public QObject {
    Q_OBJECT

private slots:
    void corpusIsThere()
    {
        // A corpus lost or moved must fail here rather than make every row below vanish.
        int files = 0;
        QDirIterator it(STRATAMESH_MALFORMED_CORPUS, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            it.next();
            files += it.fileInfo().size() < 1024;
        }
        QVERIFY2(files >= 30, qPrintable(QString::number(files)));
    }

    void smallMalformedFile_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("command");
        QDirIterator it(STRATAMESH_MALFORMED_CORPUS, QDir::Files, QDirIterator::Subdirectories);
        QStringList paths;
        while (it.hasNext()) {
            it.next();
            if (it.fileInfo().size() < 1024)
                paths << it.filePath();
        }
        paths.sort();
        const QDir root(STRATAMESH_MALFORMED_CORPUS);
        for (const QString &p : paths)
            for (const char *command : {"info", "convert"})
                QTest::newRow(qPrintable(root.relativeFilePath(p) + " " + command))
                    << p << QString::fromLatin1(command);
    }
    void smallMalformedFile()
    {
        QFETCH(QString, path);
        QFETCH(QString, command);
        QTemporaryDir dir;
        const QString output = dir.filePath(QStringLiteral("out.vtu"));
        const QStringList arguments = command == QLatin1String("info")
                                          ? QStringList{command, path}
                                          : QStringList{command, path, output};
        const ChildRun run = runChild(arguments, 20);
        QVERIFY(run.started);
        QVERIFY2(!run.timedOut, "over 20 s");
        QVERIFY2(WIFEXITED(run.status), qPrintable(QStringLiteral("killed by signal %1: %2")
                                                       .arg(WTERMSIG(run.status))
                                                       .arg(QString::fromStdString(run.err))));
        // Exit status 1: an error in the input, reported as such (2 would be bad usage).
        QVERIFY2(WEXITSTATUS(run.status) == 1, run.err.c_str());
        const QString err = QString::fromStdString(run.err);
        QVERIFY2(err.contains(path), qPrintable(err));
        QVERIFY2(!err.contains(QStringLiteral("out of memory"))
                     && !err.contains(QStringLiteral("bad_alloc")),
                 qPrintable(err));
        const long peak = run.peakKiB - baselineKiB();
        QVERIFY2(peak < limitKiB, qPrintable(QStringLiteral("peak %1 MB").arg(peak / 1024)));
        QVERIFY(!QFileInfo::exists(output));
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList());
    }
};

QTEST_GUILESS_MAIN(TestCliMalformedMemory)
#include "test_cli_malformed_memory.moc"
