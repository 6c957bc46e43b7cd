// Where the real Gocad models live, and a loud skip when they are absent.
#pragma once

#include <QString>
#include <QtTest>

namespace stratamesh::test {

// STRATAMESH_DATA_DIR, else ../shared/data beside the source tree.
QString dataDir();
// Full path of a data file, or an empty string after printing a loud warning when it is missing.
QString dataFile(const QString &name);
// True when the environment says CI=true (set by .ci/run): missing data is then a failure.
bool runningInCi();

} // namespace stratamesh::test

// Skips the current test function when a real model is not available; in CI (CI=true) a missing
// model fails it instead, so that a run without ../shared/data cannot pass. CTest shows a skipped
// data test as "Skipped", not "Passed" (SKIP_REGULAR_EXPRESSION in tests/CMakeLists.txt).
#define STRATAMESH_REQUIRE_DATA(var, name)                                                         \
    const QString var = stratamesh::test::dataFile(name);                                          \
    if (var.isEmpty()) {                                                                           \
        const QString message =                                                                    \
            QStringLiteral("*** DATA MISSING: %1 not found in %2 (set STRATAMESH_DATA_DIR) ***")   \
                .arg(name, stratamesh::test::dataDir());                                           \
        if (stratamesh::test::runningInCi())                                                       \
            QFAIL(qPrintable(message));                                                            \
        QSKIP(qPrintable(message));                                                                \
    }
