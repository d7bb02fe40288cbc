#pragma once
// Reading a .kinema file whose "simulation" block is wrong: one line that names the file and
// the JSON path, as every reader's error must.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "io/kinema_file.h"

namespace kinema::test {

// `base` with its "simulation" replaced by `simulation` is refused with one line starting
// "bad.kinema: " + expected.
inline void expectSimulationRefused(const nlohmann::ordered_json& base, const nlohmann::ordered_json& simulation,
                                    const std::string& expected) {
  nlohmann::ordered_json j = base;
  j["simulation"] = simulation;
  const Result<Scene> r = parseKinemaJson(j.dump(), "bad.kinema");
  ASSERT_FALSE(r) << expected;
  EXPECT_EQ(r.error().rfind("bad.kinema: " + expected, 0), 0u) << r.error();
  EXPECT_EQ(r.error().find('\n'), std::string::npos) << r.error();
}

}  // namespace kinema::test
