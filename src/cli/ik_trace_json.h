#pragma once
#include <nlohmann/json.hpp>

#include "ik/ik_trace.h"

namespace kinema {

// The "trace" array of `kinema ik --trace` (docs/cli.md): one object per solver step with
// iteration, step, joint (CCD steps), error and the chain's positions. `kinema demo` writes
// the same array into numbers.json, so the two can be compared entry by entry.
nlohmann::ordered_json ikTraceJson(const IkTrace& trace);

}  // namespace kinema
