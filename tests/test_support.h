#pragma once
// Helpers shared by the test files: where data lives, how many property cases to run.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "core/math.h"

namespace kinema::test {

// ../shared/data beside the checkout, or "" when it is absent.
std::string sharedDataDir();

// Case count for heavy property tests: KINEMA_PROPERTY_CASES when set (CI sets a smaller
// number), else `localDefault`.
int propertyCases(int localDefault);

// A fresh empty folder under the system temp dir, removed by the caller if it likes.
std::string makeTempDir();

// Runs a shell command; returns its exit status, stdout in `out`, stderr in `err`.
int runCommand(const std::string& command, std::string* out = nullptr, std::string* err = nullptr);

void writeFile(const std::string& path, const std::string& contents);

// A rotation drawn uniformly over all rotations (a normalised 4D Gaussian).
glm::quat randomRotation(std::mt19937& rng);
std::string readFile(const std::string& path);

}  // namespace kinema::test

// Skips the current test when ../shared/data is not beside the checkout.
#define KINEMA_REQUIRE_SHARED_DATA()                                                             \
  do {                                                                                           \
    if (::kinema::test::sharedDataDir().empty())                                                 \
      GTEST_SKIP() << "../shared/data is not beside the checkout; this test needs its files";    \
  } while (0)

#define EXPECT_VEC3_NEAR(a, b, tol)                 \
  do {                                              \
    const glm::vec3 va_ = (a), vb_ = (b);           \
    EXPECT_NEAR(va_.x, vb_.x, tol) << #a " vs " #b; \
    EXPECT_NEAR(va_.y, vb_.y, tol) << #a " vs " #b; \
    EXPECT_NEAR(va_.z, vb_.z, tol) << #a " vs " #b; \
  } while (0)

// Quaternions equal as rotations (q and -q are the same rotation).
#define EXPECT_SAME_ROTATION(a, b, tol) \
  EXPECT_NEAR(std::abs(glm::dot((a), (b))), 1.0f, tol) << #a " vs " #b
