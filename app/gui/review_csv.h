// The review of a remesh's ledger as CSV (RFC 4180: comma-separated, fields holding a comma, a
// quote or a line break are quoted with quotes doubled, CRLF line ends), one row per ledger record
// in ledger order, for a spreadsheet or a QA report:
//   record,kind,inputs,outputs,x,y,z,size,size_meaning,verdict,note
// kind and verdict are the stable keys of the JSON reports ("corner_merge", "accepted"), numbers
// are written with a decimal point whatever the locale.
#pragma once

#include "review_decisions.h"

#include "remesh/simplification_ledger.h"

#include <QString>

namespace stratamesh {

// One field, quoted when it must be.
QString csvField(const QString &text);
QString reviewCsv(const SimplificationLedger &ledger, const ReviewDecisions &decisions);
// UTF-8, through a temporary file renamed over `path`; throws FileError naming the file.
void writeReviewCsv(const QString &path, const SimplificationLedger &ledger,
                    const ReviewDecisions &decisions);

} // namespace stratamesh
