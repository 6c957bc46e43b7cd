// What the atomic writers (AtomicFile, OutputPlan) share when they create a temporary beside
// its target: the reason text of an errno, and the mode a new file gets.
#pragma once

#include <string>
#include <sys/types.h>

namespace stratamesh {

std::string systemError(int error);
// The process umask without changing it (reading it with umask() races with other threads).
mode_t currentUmask();

} // namespace stratamesh
