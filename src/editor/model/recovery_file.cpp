#include "editor/model/recovery_file.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/atomic_write.h"
#include "io/kinema_file.h"
#include "io/text_file.h"

namespace kinema {

namespace fs = std::filesystem;

namespace {

double unixSeconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

std::string filePath(const std::string& dir, long pid, const char* ext) {
  return dir + "/recovery-" + std::to_string(pid) + ext;
}

// "recovery-1234.kinema" -> 1234, or -1.
long pidOfRecoveryFile(const std::string& name) {
  const std::string prefix = "recovery-", suffix = ".kinema";
  if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return -1;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (digits.empty() || digits.size() > 9) return -1;
  for (char c : digits)
    if (c < '0' || c > '9') return -1;
  return std::stol(digits);
}

}  // namespace

std::string defaultRecoveryDir() {
  const char* xdg = std::getenv("XDG_STATE_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/kinema/recovery";
  const char* home = std::getenv("HOME");
  if (home && home[0]) return std::string(home) + "/.local/state/kinema/recovery";
  return {};
}

Autosaver::Autosaver(std::string dir, double intervalSeconds, long pid)
    : dir_(std::move(dir)), interval_(intervalSeconds), pid_(pid >= 0 ? pid : static_cast<long>(getpid())) {}

std::string Autosaver::recoveryPath() const { return filePath(dir_, pid_, ".kinema"); }
std::string Autosaver::sidecarPath() const { return filePath(dir_, pid_, ".json"); }

std::string Autosaver::tick(const Document& doc, double nowSeconds) {
  if (!started_) {
    started_ = true;
    lastWrite_ = nowSeconds;
  }
  if (!doc.dirty()) {
    if (wroteFiles_) removeFiles();  // saved: nothing left to recover
    return {};
  }
  if (doc.changeCount() == writtenChange_ || nowSeconds - lastWrite_ < interval_) return {};
  lastWrite_ = nowSeconds;
  return writeNow(doc);
}

std::string Autosaver::writeNow(const Document& doc) {
  if (dir_.empty()) return "no folder for recovery files (neither XDG_STATE_HOME nor HOME is set)";
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) return dir_ + ": cannot create the recovery folder: " + ec.message();
  // The .kinema first: a crash between the two writes leaves a file that is still offered.
  std::string error = saveKinemaFile(recoveryPath(), doc.sceneForSaving());
  if (!error.empty()) return error;
  wroteFiles_ = true;
  writtenChange_ = doc.changeCount();
  nlohmann::json side;
  side["original"] = doc.path();
  side["pid"] = pid_;
  side["time"] = unixSeconds();
  try {
    error = writeFileAtomically(sidecarPath(), side.dump(1) + "\n");
  } catch (const std::exception& e) {  // a path that is not UTF-8
    error = sidecarPath() + ": not written: " + e.what();
  }
  return error;
}

void Autosaver::removeFiles() {
  std::error_code ec;
  fs::remove(sidecarPath(), ec);
  fs::remove(recoveryPath(), ec);
  wroteFiles_ = false;
  writtenChange_ = -1;
}

bool processAlive(long pid) {
  if (pid <= 0) return false;
  return kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

std::optional<RecoverableSession> findRecoverableSession(const std::string& dir, std::string* message) {
  std::optional<RecoverableSession> best;
  if (dir.empty()) return best;
  std::error_code ec;
  fs::directory_iterator it(dir, ec), end;
  if (ec) return best;  // no folder: nothing to recover
  std::string problems;
  for (; it != end; it.increment(ec)) {
    if (ec) break;
    const std::string name = it->path().filename().string();
    const long pid = pidOfRecoveryFile(name);
    if (pid < 0 || pid == static_cast<long>(getpid()) || processAlive(pid)) continue;
    RecoverableSession s;
    s.recoveryPath = it->path().string();
    s.sidecarPath = filePath(dir, pid, ".json");
    s.pid = pid;
    std::error_code tec;
    const auto mtime = fs::last_write_time(it->path(), tec);
    if (!tec)
      s.time = std::chrono::duration<double>(mtime.time_since_epoch()).count();  // file clock; replaced below
    std::string text;
    if (fs::exists(s.sidecarPath, tec) && readTextFile(s.sidecarPath, text, 1 << 20).empty()) {
      const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
      if (j.is_object() && j.contains("original") && j["original"].is_string() && j.contains("time") &&
          j["time"].is_number()) {
        s.originalPath = j["original"].get<std::string>();
        s.time = j["time"].get<double>();
      } else {
        problems += (problems.empty() ? "" : "; ") + s.sidecarPath + ": not a recovery sidecar (original path unknown)";
      }
    }
    if (!best || s.time > best->time) best = s;
  }
  if (message) *message = problems;
  return best;
}

Result<Document> recover(const RecoverableSession& session, Autosaver& autosaver) {
  Result<Scene> scene = loadKinemaFile(session.recoveryPath);
  if (!scene) return Result<Document>::failure(scene.error() + " (" + moveCorruptRecoveryAside(session) + ")");
  Document doc(std::move(scene).value(), session.originalPath);
  doc.markModified();  // not what the original file holds
  // Our own recovery files first, then the old ones go: a crash in between loses nothing.
  const std::string error = autosaver.writeNow(doc);
  if (error.empty()) discardRecovery(session);
  return doc;
}

std::string moveCorruptRecoveryAside(const RecoverableSession& session) {
  const std::string aside = session.recoveryPath + ".corrupt";
  std::error_code ec;
  fs::rename(session.recoveryPath, aside, ec);
  if (ec) {
    // Not movable (a read-only folder): try to remove it, else the user must.
    std::error_code rec;
    if (!fs::remove(session.recoveryPath, rec) || rec)
      return "it could not be moved aside or removed (" + ec.message() + "): delete it by hand";
    fs::remove(session.sidecarPath, rec);
    return "it was removed";
  }
  fs::remove(session.sidecarPath, ec);
  return "moved aside to " + aside + ", not offered again";
}

std::string discardRecovery(const RecoverableSession& session) {
  std::error_code ec;
  fs::remove(session.sidecarPath, ec);
  fs::remove(session.recoveryPath, ec);
  if (ec) return session.recoveryPath + ": cannot remove: " + ec.message();
  return {};
}

}  // namespace kinema
