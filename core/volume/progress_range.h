// progressRange() now lives in common/progress.h with the sub-tasks it is one case of; this
// header only keeps older includes building.
#pragma once

#include "common/progress.h"
