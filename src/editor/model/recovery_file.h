#pragma once
#include <optional>
#include <string>

#include "core/result.h"
#include "editor/model/document.h"

namespace kinema {

// Autosave and crash recovery. While the document is dirty, an Autosaver writes
// recovery-PID.kinema (atomically) plus a sidecar recovery-PID.json
// {"original": PATH, "pid": PID, "time": UNIX_SECONDS} into the recovery folder. The files
// go away on a clean exit, after a save, or when the user declines recovery. At start,
// a recovery file whose writer is no longer alive is offered for recovery.

// $XDG_STATE_HOME/kinema/recovery (or ~/.local/state/kinema/recovery); "" when unknown.
std::string defaultRecoveryDir();

class Autosaver {
 public:
  // `pid`: the process the files belong to (this one by default).
  explicit Autosaver(std::string dir = defaultRecoveryDir(), double intervalSeconds = 60.0, long pid = -1);

  // Call every frame with a monotonic clock in seconds. Writes when the document is dirty,
  // changed since the last autosave and `interval` has passed since the last write (or
  // since the first tick); removes the files once the document is clean (saved).
  // Returns "" or the one-line error of a failed write.
  std::string tick(const Document& doc, double nowSeconds);
  std::string writeNow(const Document& doc);
  // Clean exit, after a save, or recovery declined: the files are deleted.
  void removeFiles();

  std::string recoveryPath() const;  // dir/recovery-PID.kinema
  std::string sidecarPath() const;   // dir/recovery-PID.json
  const std::string& dir() const { return dir_; }
  long pid() const { return pid_; }

 private:
  std::string dir_;
  double interval_;
  long pid_;
  bool started_ = false;
  double lastWrite_ = 0.0;
  long long writtenChange_ = -1;
  bool wroteFiles_ = false;
};

struct RecoverableSession {
  std::string recoveryPath;  // the .kinema to load
  std::string sidecarPath;   // may not exist (a crash between the two writes)
  std::string originalPath;  // the file the user was editing ("" for a new document)
  long pid = -1;
  double time = 0.0;  // unix seconds of the autosave
};

// True when a process with this id exists.
bool processAlive(long pid);

// The newest recovery file in `dir` whose writer is gone (never this process's own).
// `message` gets a line about files that could not be read (they are skipped).
std::optional<RecoverableSession> findRecoverableSession(const std::string& dir = defaultRecoveryDir(),
                                                         std::string* message = nullptr);
// Loads the recovered document (dirty, with the original path) and hands its files over
// to `autosaver` (renamed to its pid), so a second crash loses nothing. A file that does
// not load is moved aside (moveCorruptRecoveryAside) and the error says where.
Result<Document> recover(const RecoverableSession& session, Autosaver& autosaver);
// A recovery file that does not load: renamed to PATH.corrupt (kept for the user, no longer
// matching recovery-PID.kinema, so it is reported once) and its sidecar removed. Returns
// what happened, for the error message. recover() calls it on a failed load.
std::string moveCorruptRecoveryAside(const RecoverableSession& session);
// The user declined: deletes the session's files. "" or the error.
std::string discardRecovery(const RecoverableSession& session);

}  // namespace kinema
