#include "io/atomic_write.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <vector>

namespace kinema {

namespace {

// ---- Temporary files removed on SIGTERM / SIGINT / SIGHUP ----
// The handler may only use async-signal-safe calls: the paths live in fixed buffers, each
// guarded by a lock-free atomic (0 free, 1 being filled, 2 holds a path to remove).
constexpr int kSlots = 16;          // saves in flight at once (threads); more are not guarded
constexpr size_t kSlotBytes = 4096;  // PATH_MAX
char gTempPaths[kSlots][kSlotBytes];
std::atomic<int> gSlotState[kSlots];
constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};
struct sigaction gPrevious[3];

extern "C" void removeTempFilesOnSignal(int sig, siginfo_t* info, void* context) {
  const int savedErrno = errno;
  for (int i = 0; i < kSlots; ++i)
    if (gSlotState[i].load() == 2) ::unlink(gTempPaths[i]);
  for (int k = 0; k < 3; ++k) {
    if (kSignals[k] != sig) continue;
    const struct sigaction& prev = gPrevious[k];
    if (prev.sa_flags & SA_SIGINFO) {
      prev.sa_sigaction(sig, info, context);
    } else if (prev.sa_handler == SIG_DFL) {
      // Terminate as the signal would have: it is delivered again once this handler returns.
      ::sigaction(sig, &prev, nullptr);
      ::raise(sig);
    } else if (prev.sa_handler != SIG_IGN) {
      prev.sa_handler(sig);
    }
  }
  errno = savedErrno;
}

void installSignalCleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int k = 0; k < 3; ++k) {
      struct sigaction current {};
      if (::sigaction(kSignals[k], nullptr, &current) != 0) continue;
      if (!(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_IGN) continue;  // ignored: nothing ends us
      gPrevious[k] = current;
      struct sigaction ours {};
      ours.sa_sigaction = removeTempFilesOnSignal;
      ours.sa_flags = SA_SIGINFO | SA_RESTART;
      sigemptyset(&ours.sa_mask);
      ::sigaction(kSignals[k], &ours, nullptr);
    }
  });
}

// One temporary file known to the signal handler while it exists.
class GuardedTemp {
 public:
  void set(const char* path) {
    if (std::strlen(path) >= kSlotBytes) return;
    for (int i = 0; i < kSlots; ++i) {
      int expected = 0;
      if (!gSlotState[i].compare_exchange_strong(expected, 1)) continue;
      std::strcpy(gTempPaths[i], path);
      gSlotState[i].store(2);
      slot_ = i;
      return;
    }
  }
  void release() {
    if (slot_ >= 0) gSlotState[slot_].store(0);
    slot_ = -1;
  }
  ~GuardedTemp() { release(); }

 private:
  int slot_ = -1;
};

// Blocks the cleanup signals while a temporary file is created and registered, so none
// can arrive in between and leave it behind.
class BlockedSignals {
 public:
  BlockedSignals() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : kSignals) sigaddset(&set, s);
    ::pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~BlockedSignals() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

// ---- Paths ----

// A save through a symbolic link replaces the file it points to, not the link.
std::string resolveLinks(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
  char* real = ::realpath(path.c_str(), nullptr);
  if (!real) return path;  // a dangling link: replace the link itself
  std::string out(real);
  std::free(real);
  return out;
}

std::string folderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

std::string nameOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// "a character device" for what is there and is not a regular file; "" for a regular file
// or nothing.
std::string notRegularKind(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return {};
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISCHR(st.st_mode)) return "a character device";
  if (S_ISBLK(st.st_mode)) return "a block device";
  if (S_ISFIFO(st.st_mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

bool processAlive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

// Removes temporaries of `path` left by writers that are gone (killed mid-save). Only
// regular files whose name carries a dead pid: a live writer's file is never touched.
void removeStaleTemps(const std::string& path) {
  const std::string dir = folderOf(path), base = nameOf(path);
  DIR* d = ::opendir(dir.c_str());
  if (!d) return;
  const long self = static_cast<long>(::getpid());
  std::vector<std::string> stale;
  while (const dirent* e = ::readdir(d)) {
    const long pid = atomicWriteTempPid(e->d_name, base);
    if (pid < 0 || pid == self || processAlive(pid)) continue;
    stale.push_back(dir + "/" + e->d_name);
  }
  ::closedir(d);
  for (const std::string& file : stale) {
    struct stat st {};
    if (::lstat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::unlink(file.c_str());
  }
}

// Flushes the rename itself to disk (the folder's entry), best effort.
void syncFolderOf(const std::string& path) {
  const int fd = ::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

long atomicWriteTempPid(const std::string& name, const std::string& base) {
  const std::string prefix = base + ".tmp-";
  if (name.compare(0, prefix.size(), prefix) != 0) return -1;
  size_t i = prefix.size(), digits = 0;
  long pid = 0;
  while (i < name.size() && name[i] >= '0' && name[i] <= '9' && digits < 10) {
    pid = pid * 10 + (name[i] - '0');
    ++i;
    ++digits;
  }
  if (digits == 0 || i >= name.size() || name[i] != '-' || name.size() - i - 1 != 6) return -1;
  for (size_t k = i + 1; k < name.size(); ++k) {
    const char c = name[k];
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'))) return -1;
  }
  return pid;
}

std::string writeFileAtomically(const std::string& requested, const std::string& contents) {
  const std::string path = resolveLinks(requested);
  if (const std::string kind = notRegularKind(path); !kind.empty())
    return requested + ": not saved: " + (path != requested ? "it links to " + path + ", which is " : "it is ") +
           kind + ", not a regular file";
  installSignalCleanup();
  removeStaleTemps(path);
  const std::string pattern = path + ".tmp-" + std::to_string(static_cast<long>(::getpid())) + "-XXXXXX";
  std::vector<char> tmp(pattern.begin(), pattern.end());
  tmp.push_back('\0');
  GuardedTemp guard;
  int fd = -1;
  {
    BlockedSignals blocked;
    fd = ::mkstemp(tmp.data());
    if (fd >= 0) guard.set(tmp.data());
  }
  if (fd < 0) return requested + ": cannot create a temporary file beside it: " + std::strerror(errno);
  const std::string tmpPath(tmp.data());
  auto failWith = [&](const char* what) {
    const std::string message = requested + ": " + what + ": " + std::strerror(errno);
    ::close(fd);
    ::unlink(tmpPath.c_str());
    return message;
  };
  // mkstemp creates 0600: keep the replaced file's permissions, or use the usual ones.
  struct stat old {};
  if (::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode)) {
    ::fchmod(fd, old.st_mode & 07777);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
  const char* p = contents.data();
  size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return failWith("write failed");
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) return failWith("flush to disk failed");
  if (::close(fd) != 0) {
    const std::string message = requested + ": close failed: " + std::strerror(errno);
    ::unlink(tmpPath.c_str());
    return message;
  }
  if (::rename(tmpPath.c_str(), path.c_str()) != 0) {
    const std::string message = requested + ": cannot replace the file: " + std::strerror(errno);
    ::unlink(tmpPath.c_str());
    return message;
  }
  guard.release();
  syncFolderOf(path);
  return {};
}

}  // namespace kinema
