#include "io/atomic_write.h"

#include <dirent.h>
#include <grp.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/default_character.h"
#include "io/kinema_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::readFile;
using test::writeFile;

// A temporary folder removed (with everything in it) at the end of the test.
struct TempDir {
  std::string path = test::makeTempDir();
  TempDir() { EXPECT_FALSE(path.empty()); }
  ~TempDir() {
    ::chmod(path.c_str(), 0700);
    test::runCommand("chmod -R u+rwx '" + path + "' && rm -rf '" + path + "'");
  }
  std::string operator/(const std::string& name) const { return path + "/" + name; }
};

std::vector<std::string> listDir(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") names.push_back(n);
    }
    ::closedir(d);
  }
  return names;
}

// Names of leftover temporary files ("NAME.tmp-XXXXXX") in `dir`.
std::vector<std::string> tempFiles(const std::string& dir) {
  std::vector<std::string> found;
  for (const std::string& n : listDir(dir))
    if (n.find(".tmp-") != std::string::npos) found.push_back(n);
  return found;
}

bool exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

Scene defaultScene() {
  Scene scene;
  scene.skeleton = makeDefaultCharacter();
  return scene;
}

// Runs `body` in a forked child; returns its exit status (or 128 + signal) and whatever it
// wrote to `message` (passed back through a pipe).
struct ChildResult {
  int status = -1;
  std::string message;
};

ChildResult runInChild(const std::function<int(std::string&)>& body) {
  int fds[2];
  ChildResult result;
  if (::pipe(fds) != 0) return result;
  const pid_t pid = ::fork();
  if (pid < 0) return result;
  if (pid == 0) {
    ::close(fds[0]);
    std::string message;
    const int code = body(message);
    size_t off = 0;
    while (off < message.size()) {
      const ssize_t n = ::write(fds[1], message.data() + off, message.size() - off);
      if (n <= 0) break;
      off += static_cast<size_t>(n);
    }
    ::close(fds[1]);
    ::_exit(code);  // no gtest teardown, no atexit handlers in the child
  }
  ::close(fds[1]);
  char buf[4096];
  ssize_t n;
  while ((n = ::read(fds[0], buf, sizeof buf)) > 0) result.message.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

// Child exit codes.
constexpr int kSaved = 0;
constexpr int kSaveFailed = 10;
constexpr int kSetupFailed = 20;

// -------------------------------------------------------------------------------------

TEST(AtomicWrite, CreatesANewFile) {
  TempDir dir;
  const std::string path = dir / "new.txt";
  ASSERT_FALSE(exists(path));
  EXPECT_EQ(writeFileAtomically(path, "hello\n"), "");
  EXPECT_EQ(readFile(path), "hello\n");
  EXPECT_EQ(listDir(dir.path), std::vector<std::string>{"new.txt"});
}

TEST(AtomicWrite, ReplacesAnExistingFile) {
  TempDir dir;
  const std::string path = dir / "f.txt";
  writeFile(path, std::string(10000, 'x'));
  EXPECT_EQ(writeFileAtomically(path, "short"), "");
  EXPECT_EQ(readFile(path), "short");  // replaced, not overwritten in place (no tail of x)
  EXPECT_EQ(writeFileAtomically(path, ""), "");
  EXPECT_TRUE(exists(path));
  EXPECT_EQ(readFile(path), "");
  EXPECT_TRUE(tempFiles(dir.path).empty());
  EXPECT_EQ(listDir(dir.path).size(), 1u);
}

TEST(AtomicWrite, WritesBinaryAndLargeContentsExactly) {
  TempDir dir;
  std::string data;
  for (int i = 0; i < 3 * 1024 * 1024; ++i) data += static_cast<char>((i * 131) & 0xff);
  data[5] = '\0';
  const std::string path = dir / "big.bin";
  EXPECT_EQ(writeFileAtomically(path, data), "");
  EXPECT_EQ(readFile(path), data);
}

TEST(AtomicWrite, ManySavesLeaveNoTemporaryFiles) {
  TempDir dir;
  const std::string path = dir / "scene.kinema";
  Scene scene = defaultScene();
  for (int i = 0; i < 5; ++i) {
    scene.skeleton.rest[0].translation.x = static_cast<float>(i);
    ASSERT_EQ(saveKinemaFile(path, scene), "");
  }
  EXPECT_EQ(listDir(dir.path), std::vector<std::string>{"scene.kinema"});
  const Result<Scene> back = loadKinemaFile(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->skeleton.rest[0].translation.x, 4.0f);
}

TEST(AtomicWrite, NewFileGetsReadablePermissions) {
  // mkstemp creates 0600; the saved file must not stay private to its owner.
  TempDir dir;
  const std::string path = dir / "perm.txt";
  const mode_t old = ::umask(022);
  const std::string error = writeFileAtomically(path, "x");
  ::umask(old);
  ASSERT_EQ(error, "");
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST(AtomicWrite, ReplacedFileKeepsItsPermissions) {
  TempDir dir;
  const std::string path = dir / "private.kinema";
  writeFile(path, "old");
  ASSERT_EQ(::chmod(path.c_str(), 0600), 0);
  EXPECT_EQ(writeFileAtomically(path, "new"), "");
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(readFile(path), "new");
}

TEST(AtomicWrite, SavingThroughASymlinkReplacesTheTargetAndKeepsTheLink) {
  TempDir dir;
  const std::string target = dir / "real.kinema", link = dir / "link.kinema";
  writeFile(target, "old");
  ASSERT_EQ(::symlink(target.c_str(), link.c_str()), 0);
  EXPECT_EQ(writeFileAtomically(link, "new"), "");
  struct stat st {};
  ASSERT_EQ(::lstat(link.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode)) << "the link was replaced by a regular file";
  EXPECT_EQ(readFile(target), "new");
  EXPECT_TRUE(tempFiles(dir.path).empty());
}

TEST(AtomicWrite, MissingFolderFailsNamingThePath) {
  TempDir dir;
  const std::string path = dir / "no/such/folder/scene.kinema";
  const std::string error = writeFileAtomically(path, "data");
  ASSERT_FALSE(error.empty());
  EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_FALSE(exists(path));
  const std::string viaSave = saveKinemaFile(path, defaultScene());
  ASSERT_FALSE(viaSave.empty());
  EXPECT_EQ(viaSave.rfind(path + ": ", 0), 0u) << viaSave;
  EXPECT_EQ(listDir(dir.path), std::vector<std::string>{});
}

TEST(AtomicWrite, PathThatIsAFolderFailsAndKeepsTheFolder) {
  TempDir dir;
  const std::string sub = dir / "sub";
  ASSERT_EQ(::mkdir(sub.c_str(), 0755), 0);
  writeFile(sub + "/inside.txt", "keep");
  const std::string error = writeFileAtomically(sub, "data");
  ASSERT_FALSE(error.empty());
  EXPECT_EQ(error.rfind(sub + ": ", 0), 0u) << error;
  EXPECT_EQ(readFile(sub + "/inside.txt"), "keep");
  EXPECT_TRUE(tempFiles(dir.path).empty()) << tempFiles(dir.path)[0];
}

TEST(AtomicWrite, InvalidSceneIsNotSavedAndTheFileIsUntouched) {
  TempDir dir;
  const std::string path = dir / "scene.kinema";
  const Scene good = defaultScene();
  ASSERT_EQ(saveKinemaFile(path, good), "");
  const std::string before = readFile(path);
  ASSERT_FALSE(before.empty());

  Scene nanRest = good;
  nanRest.skeleton.rest[3].translation.y = std::numeric_limits<float>::quiet_NaN();
  Scene infScale = good;
  infScale.skeleton.rest[0].scale.z = std::numeric_limits<float>::infinity();
  Scene badParent = good;
  badParent.skeleton.parents[2] = 5;  // after its child
  Scene badClip = good;
  badClip.clips.push_back(Clip{"c", {Channel{99, ChannelTarget::Rotation, Interpolation::Linear, {0.0f}, {glm::vec4(0, 0, 0, 1)}}}, 0.0});
  Scene nanKey = good;
  nanKey.clips.push_back(Clip{"c", {Channel{1, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f},
                                            {glm::vec4(0.0f), glm::vec4(std::nanf(""), 0, 0, 0)}}}, 0.0});
  Scene equalTimes = good;
  equalTimes.clips.push_back(Clip{"c", {Channel{1, ChannelTarget::Scale, Interpolation::Step, {1.0f, 1.0f},
                                               {glm::vec4(1.0f), glm::vec4(1.0f)}}}, 0.0});

  const std::pair<const char*, const Scene*> cases[] = {
      {"NaN rest translation", &nanRest}, {"infinite scale", &infScale}, {"parent after child", &badParent},
      {"channel of a missing joint", &badClip}, {"NaN key", &nanKey}, {"equal key times", &equalTimes}};
  for (const auto& [what, scene] : cases) {
    const std::string error = saveKinemaFile(path, *scene);
    EXPECT_FALSE(error.empty()) << what;
    EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << what << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << what << ": " << error;
    EXPECT_EQ(readFile(path), before) << what;
    EXPECT_EQ(listDir(dir.path), std::vector<std::string>{"scene.kinema"}) << what;
  }
  // Nor is a new file created for an invalid scene.
  EXPECT_NE(saveKinemaFile(dir / "fresh.kinema", nanRest), "");
  EXPECT_FALSE(exists(dir / "fresh.kinema"));
}

// THE KEY CASE, (a): the disk "fills up" half way through the save. RLIMIT_FSIZE makes
// write() fail with EFBIG (SIGXFSZ ignored) whoever the user is, root included.
TEST(AtomicWrite, FailedWriteNeverDestroysThePreviousFile) {
  TempDir dir;
  const std::string path = dir / "scene.kinema";
  const std::string previous = "previous contents, which must survive\n";
  writeFile(path, previous);
  Scene scene = defaultScene();
  const size_t size = toKinemaJson(scene).size();
  ASSERT_GT(size, 2000u);

  auto saveUnderLimit = [&](rlim_t limit) {
    return runInChild([&, limit](std::string& message) {
      ::signal(SIGXFSZ, SIG_IGN);
      struct rlimit rl {};
      rl.rlim_cur = rl.rlim_max = limit;
      if (::setrlimit(RLIMIT_FSIZE, &rl) != 0) return kSetupFailed;
      message = saveKinemaFile(path, scene);
      return message.empty() ? kSaved : kSaveFailed;
    });
  };

  // The limit cuts the file off after 1000 bytes: the save must fail...
  const ChildResult failed = saveUnderLimit(1000);
  ASSERT_EQ(failed.status, kSaveFailed) << failed.message;
  EXPECT_EQ(failed.message.rfind(path + ": ", 0), 0u) << failed.message;
  EXPECT_EQ(failed.message.find('\n'), std::string::npos) << failed.message;
  // ...and leave the old file byte for byte, with no temporary file beside it.
  EXPECT_EQ(readFile(path), previous);
  EXPECT_EQ(listDir(dir.path), std::vector<std::string>{"scene.kinema"});

  // Control: the same child with room enough does save (so the failure above came from
  // the limit, not from the fork or the set-up).
  const ChildResult saved = saveUnderLimit(static_cast<rlim_t>(size) + 4096);
  ASSERT_EQ(saved.status, kSaved) << saved.message;
  EXPECT_EQ(readFile(path), toKinemaJson(scene));
  EXPECT_TRUE(tempFiles(dir.path).empty());
}

// (b): the folder cannot be written. Root ignores permission bits, so as root the child
// first becomes "nobody" (65534); the folder, owned by root, is made read-only.
TEST(AtomicWrite, UnwritableFolderNeverDestroysThePreviousFile) {
  TempDir dir;
  ASSERT_EQ(::chmod(dir.path.c_str(), 0755), 0);  // nobody may enter, not write
  const std::string locked = dir / "locked";
  const std::string open = dir / "open";
  ASSERT_EQ(::mkdir(locked.c_str(), 0755), 0);
  ASSERT_EQ(::mkdir(open.c_str(), 0755), 0);
  const std::string path = locked + "/scene.kinema";
  const std::string previous = "old scene\n";
  writeFile(path, previous);
  ASSERT_EQ(::chmod(path.c_str(), 0666), 0);  // even a writable file is replaced only via the folder
  ASSERT_EQ(::chmod(locked.c_str(), 0555), 0);
  ASSERT_EQ(::chmod(open.c_str(), 0777), 0);
  const bool root = ::geteuid() == 0;

  auto saveAs = [&](const std::string& target) {
    return runInChild([&, target](std::string& message) {
      if (root && (::setgroups(0, nullptr) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0))
        return kSetupFailed;
      message = saveKinemaFile(target, defaultScene());
      return message.empty() ? kSaved : kSaveFailed;
    });
  };

  const ChildResult failed = saveAs(path);
  ASSERT_EQ(failed.status, kSaveFailed) << failed.message;
  EXPECT_EQ(failed.message.rfind(path + ": ", 0), 0u) << failed.message;
  EXPECT_EQ(readFile(path), previous);
  EXPECT_EQ(listDir(locked), std::vector<std::string>{"scene.kinema"});

  // Control: the same (unprivileged) child can save into a writable folder.
  const ChildResult saved = saveAs(open + "/scene.kinema");
  ASSERT_EQ(saved.status, kSaved) << saved.message;
  EXPECT_EQ(readFile(open + "/scene.kinema"), toKinemaJson(defaultScene()));
  EXPECT_EQ(listDir(open), std::vector<std::string>{"scene.kinema"});
}

// (c): a real full disk. A 16 KiB tmpfs holds the previous file; the new one does not fit,
// so write() fails with ENOSPC part way. Needs root to mount (CI runs as root).
TEST(AtomicWrite, FullDiskNeverDestroysThePreviousFile) {
  if (::geteuid() != 0) GTEST_SKIP() << "mounting a small tmpfs needs root";
  TempDir dir;
  const std::string disk = dir / "disk";
  ASSERT_EQ(::mkdir(disk.c_str(), 0755), 0);
  if (test::runCommand("mount -t tmpfs -o size=16k kinema-full-disk '" + disk + "' 2>/dev/null") != 0)
    GTEST_SKIP() << "this machine does not allow mounting a tmpfs (no CAP_SYS_ADMIN)";
  struct Unmount {
    std::string path;
    ~Unmount() { test::runCommand("umount '" + path + "'"); }
  } unmount{disk};

  const std::string path = disk + "/scene.kinema";
  const std::string previous = "previous contents, which must survive\n";
  writeFile(path, previous);
  // A scene whose file is far larger than the disk: one long clip on the default character.
  Scene scene = defaultScene();
  Clip clip;
  clip.name = "long";
  Channel ch;
  ch.joint = 0;
  ch.target = ChannelTarget::Translation;
  for (int k = 0; k < 5000; ++k) {
    ch.times.push_back(k / 30.0f);
    ch.values.emplace_back(k * 0.001f, 1.0f, -k * 0.002f, 0.0f);
  }
  clip.channels.push_back(ch);
  scene.clips.push_back(clip);
  ASSERT_GT(toKinemaJson(scene).size(), 64u * 1024u);

  const std::string error = saveKinemaFile(path, scene);
  ASSERT_NE(error, "") << "the save cannot have fitted on a 16 KiB disk";
  EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
  EXPECT_NE(error.find(std::strerror(ENOSPC)), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_EQ(readFile(path), previous);
  EXPECT_EQ(listDir(disk), std::vector<std::string>{"scene.kinema"});
  // Control: a scene that fits is saved on the same disk.
  EXPECT_EQ(saveKinemaFile(path, defaultScene()), "");
  EXPECT_EQ(readFile(path), toKinemaJson(defaultScene()));
}

}  // namespace
}  // namespace kinema
