// Issue 19, saving: never through a link onto a device or other non-regular file; the
// temporary file goes on SIGTERM; one left by a killed writer (SIGKILL) is removed by the
// next save of the same file, and only when its writer is gone.
#include <dirent.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "io/atomic_write.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

struct Folder {
  std::string path = test::makeTempDir();
  ~Folder() { test::runCommand("rm -rf '" + path + "'"); }
  std::string operator/(const std::string& name) const { return path + "/" + name; }
};

std::vector<std::string> temporaries(const std::string& dir) {
  std::vector<std::string> found;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d))
      if (std::string(e->d_name).find(".tmp-") != std::string::npos) found.push_back(e->d_name);
    ::closedir(d);
  }
  return found;
}

bool exists(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0;
}

TEST(SaveSafety, NeverWritesThroughALinkOntoADeviceOrFifo) {
  Folder dir;
  struct stat before {};
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  ASSERT_TRUE(S_ISCHR(before.st_mode));
  const std::string link = dir / "scene.kinema";
  ASSERT_EQ(::symlink("/dev/null", link.c_str()), 0);
  const std::string error = writeFileAtomically(link, "data");
  EXPECT_EQ(error, link + ": not saved: it links to /dev/null, which is a character device, not a regular file");
  struct stat after {};
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode)) << "the device node was replaced";
  EXPECT_EQ(after.st_rdev, before.st_rdev);
  // A FIFO named directly: refused, and still a FIFO.
  const std::string fifo = dir / "pipe.bvh";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  EXPECT_EQ(writeFileAtomically(fifo, "data"), fifo + ": not saved: it is a FIFO (named pipe), not a regular file");
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_TRUE(temporaries(dir.path).empty());
  // A link to a regular file still saves through it (the link stays).
  const std::string real = dir / "real.kinema", alias = dir / "alias.kinema";
  test::writeFile(real, "old");
  ASSERT_EQ(::symlink(real.c_str(), alias.c_str()), 0);
  EXPECT_EQ(writeFileAtomically(alias, "new"), "");
  EXPECT_EQ(test::readFile(real), "new");
}

TEST(SaveSafety, TemporaryNamesCarryTheWriterPid) {
  EXPECT_EQ(atomicWriteTempPid("a.kinema.tmp-1234-Ab9xYz", "a.kinema"), 1234);
  EXPECT_EQ(atomicWriteTempPid("a.kinema.tmp-Ab9xYz", "a.kinema"), -1);         // the old name: no pid
  EXPECT_EQ(atomicWriteTempPid("b.kinema.tmp-1234-Ab9xYz", "a.kinema"), -1);    // another file's
  EXPECT_EQ(atomicWriteTempPid("a.kinema.tmp-1234-Ab9xY", "a.kinema"), -1);     // 5 random letters
  EXPECT_EQ(atomicWriteTempPid("a.kinema.tmp-1234-Ab9x/z", "a.kinema"), -1);
  EXPECT_EQ(atomicWriteTempPid("a.kinema.tmp--Ab9xYz", "a.kinema"), -1);
}

// A child that saves `bytes` bytes to `path`; returns its pid once its temporary file is
// being written (non-empty), or -1 after 20 s.
pid_t startBigSave(const std::string& dir, const std::string& path, size_t bytes) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string contents(bytes, 'k');
    ::_exit(writeFileAtomically(path, contents).empty() ? 0 : 1);
  }
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < until) {
    for (const std::string& name : temporaries(dir)) {
      struct stat st {};
      if (::stat((dir + "/" + name).c_str(), &st) == 0 && st.st_size > 0) return pid;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  return -1;
}

constexpr size_t kBigSave = size_t(256) << 20;  // long enough to be caught mid-write

TEST(SaveSafety, SigtermDuringASaveRemovesTheTemporaryFileAndKeepsTheOldOne) {
  Folder dir;
  const std::string path = dir / "scene.kinema";
  test::writeFile(path, "previous");
  const pid_t pid = startBigSave(dir.path, path, kBigSave);
  ASSERT_GT(pid, 0) << "the child's temporary file never appeared";
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  // Killed by the signal itself (the handler hands it on), before the rename.
  ASSERT_TRUE(WIFSIGNALED(status)) << "the save finished before SIGTERM arrived";
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(test::readFile(path), "previous");
  EXPECT_EQ(temporaries(dir.path), std::vector<std::string>{});
}

TEST(SaveSafety, TheNextSaveRemovesOnlyTemporariesOfDeadWriters) {
  Folder dir;
  const std::string path = dir / "scene.kinema";
  test::writeFile(path, "previous");
  const pid_t pid = startBigSave(dir.path, path, kBigSave);
  ASSERT_GT(pid, 0);
  ASSERT_EQ(::kill(pid, SIGKILL), 0);  // no handler runs: the temporary stays
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status));
  const std::vector<std::string> left = temporaries(dir.path);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(atomicWriteTempPid(left[0], "scene.kinema"), pid);
  // A temporary of a live writer (pid 1 always exists), one of another file, and the old
  // pid-less name: none of them may go.
  const std::string live = path + ".tmp-1-aaaaaa", other = dir / "other.kinema.tmp-" + std::to_string(pid) + "-bbbbbb",
                    old = path + ".tmp-cccccc";
  for (const std::string& f : {live, other, old}) test::writeFile(f, "x");
  EXPECT_EQ(writeFileAtomically(path, "new"), "");
  EXPECT_EQ(test::readFile(path), "new");
  EXPECT_FALSE(exists(dir / left[0])) << "the killed writer's temporary is still there";
  EXPECT_TRUE(exists(live));
  EXPECT_TRUE(exists(other));
  EXPECT_TRUE(exists(old));
}

}  // namespace
}  // namespace kinema
