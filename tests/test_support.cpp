#include "test_support.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace kinema::test {

std::string sharedDataDir() {
  struct stat st {};
  const std::string dir = KINEMA_SHARED_DATA_DIR;
  if (::stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return dir;
  return {};
}

int propertyCases(int localDefault) {
  if (const char* v = std::getenv("KINEMA_PROPERTY_CASES")) {
    const int n = std::atoi(v);
    if (n > 0) return n;
  }
  return localDefault;
}

std::string makeTempDir() {
  const char* base = std::getenv("TMPDIR");
  std::string pattern = std::string(base && *base ? base : "/tmp") + "/kinema-test-XXXXXX";
  if (!::mkdtemp(pattern.data())) return {};
  return pattern;
}

int runCommand(const std::string& command, std::string* out, std::string* err) {
  const std::string dir = makeTempDir();
  const std::string o = dir + "/out", e = dir + "/err";
  const int status = std::system((command + " >" + o + " 2>" + e).c_str());
  if (out) *out = readFile(o);
  if (err) *err = readFile(e);
  std::system(("rm -rf '" + dir + "'").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

glm::quat randomRotation(std::mt19937& rng) {
  std::normal_distribution<float> n(0.0f, 1.0f);
  glm::quat q;
  do {
    q = glm::quat(n(rng), n(rng), n(rng), n(rng));
  } while (glm::dot(q, q) < 1e-4f);
  return glm::normalize(q);
}

void writeFile(const std::string& path, const std::string& contents) {
  std::ofstream f(path, std::ios::binary);
  f << contents;
}

std::string readFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace kinema::test
