// Where the real Gocad models live, and a loud skip when they are absent.
#pragma once

#include <QString>
#include <QtTest>

namespace stratamesh::test {

// STRATAMESH_DATA_DIR, else ../shared/data beside the source tree.
QString dataDir();
// Full path of a data file, or an empty string after printing a loud warning when it is missing.
QString dataFile(const QString &name);

} // namespace stratamesh::test

// Skips the current test function when a real model is not available.
#define STRATAMESH_REQUIRE_DATA(var, name)                                                         \
    const QString var = stratamesh::test::dataFile(name);                                          \
    if (var.isEmpty())                                                                             \
        QSKIP(qPrintable(                                                                          \
            QStringLiteral("*** DATA MISSING: %1 not found in %2 (set STRATAMESH_DATA_DIR) ***")   \
                .arg(name, stratamesh::test::dataDir())));
