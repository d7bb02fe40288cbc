#pragma once
// The `kinema simulate` CLI tests' fixture: a temporary folder, scenes saved into it as
// .kinema files, the binary run with stdout and stderr kept.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "io/kinema_file.h"
#include "scene/scene.h"
#include "test_support.h"

namespace kinema::test {

class SimulateCliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeTempDir();
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  std::string save(const Scene& scene, const std::string& name) {
    const std::string path = dir_ + "/" + name;
    EXPECT_EQ(saveKinemaFile(path, scene), "");
    return path;
  }
  // `kinema simulate ARGS`.
  int kinema(const std::string& args) { return runCommand(std::string(KINEMA_BINARY) + " simulate " + args, &out_, &err_); }
  static bool exists(const std::string& path) { return std::ifstream(path).good(); }
  std::string dir_, out_, err_;
};

}  // namespace kinema::test
