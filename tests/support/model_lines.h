// Lines of a model counted by the kinds of surfaces meeting along them: remesh tests use it to see
// whether a fault throw was cancelled (two horizon pieces on one fault line) or a crossing kept.
#pragma once

#include "model/model.h"

#include <functional>

namespace stratamesh::test {

// Lines whose incident surfaces (horizons, faults) satisfy `accept`.
int countLines(const Model &model, const std::function<bool(int horizons, int faults)> &accept);

} // namespace stratamesh::test
