// Autosave + crash recovery: timing of autosaves, what is offered, and a real crash (a
// forked child killed with SIGKILL after it autosaved).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>

#include "editor/model/document_files.h"
#include "editor/model/pose_edits.h"
#include "editor/model/recovery_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

namespace fs = std::filesystem;

const glm::quat kEdit = glm::angleAxis(0.6f, glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f)));

TEST(RecoveryFile, AutosavesEverySixtySecondsWhileDirtyAndCleansUpAfterASave) {
  const std::string dir = test::makeTempDir() + "/state/kinema/recovery";  // created on demand
  Document doc = newDocument();
  Autosaver saver(dir, 60.0);
  EXPECT_EQ(saver.tick(doc, 100.0), "");
  ASSERT_EQ(setJointRotation(doc, 3, kEdit), "");
  EXPECT_EQ(saver.tick(doc, 159.0), "");
  EXPECT_FALSE(fs::exists(saver.recoveryPath()));  // 59 s after the start: not yet
  EXPECT_EQ(saver.tick(doc, 160.0), "");
  ASSERT_TRUE(fs::exists(saver.recoveryPath()));
  ASSERT_TRUE(fs::exists(saver.sidecarPath()));
  const auto written = fs::last_write_time(saver.recoveryPath());
  fs::remove(saver.recoveryPath());
  EXPECT_EQ(saver.tick(doc, 400.0), "");  // nothing changed since: no second write
  EXPECT_FALSE(fs::exists(saver.recoveryPath()));
  ASSERT_EQ(setJointRotation(doc, 4, kEdit), "");
  EXPECT_EQ(saver.tick(doc, 401.0), "");
  EXPECT_TRUE(fs::exists(saver.recoveryPath()));
  (void)written;
  ASSERT_EQ(saveDocumentAs(doc, fs::path(dir).parent_path().string() + "/saved.kinema"), "");
  EXPECT_EQ(saver.tick(doc, 402.0), "");  // saved: the recovery files go
  EXPECT_FALSE(fs::exists(saver.recoveryPath()));
  EXPECT_FALSE(fs::exists(saver.sidecarPath()));
  fs::remove_all(fs::path(dir).parent_path().parent_path().parent_path());
}

TEST(RecoveryFile, OnlyFilesOfDeadProcessesAreOffered) {
  const std::string dir = test::makeTempDir();
  Document doc = newDocument();
  ASSERT_EQ(setJointRotation(doc, 3, kEdit), "");
  Autosaver mine(dir);
  ASSERT_EQ(mine.writeNow(doc), "");
  EXPECT_FALSE(findRecoverableSession(dir).has_value());  // our own files
  Autosaver live(dir, 60.0, static_cast<long>(getppid()));  // a process that is alive
  ASSERT_EQ(live.writeNow(doc), "");
  EXPECT_FALSE(findRecoverableSession(dir).has_value());
  // A left-over .kinema without its sidecar, from a pid that cannot exist.
  fs::copy_file(mine.recoveryPath(), dir + "/recovery-999999999.kinema");
  std::optional<RecoverableSession> s = findRecoverableSession(dir);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->pid, 999999999);
  EXPECT_EQ(s->originalPath, "");
  // A corrupt sidecar: still offered (the .kinema is what matters), with a message.
  test::writeFile(dir + "/recovery-999999999.json", "{\"original\": 3");
  std::string message;
  s = findRecoverableSession(dir, &message);
  ASSERT_TRUE(s.has_value());
  EXPECT_NE(message.find("recovery-999999999.json"), std::string::npos) << message;
  EXPECT_EQ(discardRecovery(*s), "");
  EXPECT_FALSE(fs::exists(dir + "/recovery-999999999.json"));
  EXPECT_FALSE(fs::exists(dir + "/recovery-999999999.kinema"));
  EXPECT_FALSE(findRecoverableSession(dir).has_value());
  EXPECT_FALSE(findRecoverableSession(dir + "/missing").has_value());
  mine.removeFiles();
  live.removeFiles();
  fs::remove_all(dir);
}

// Issue 19: a recovery file that does not load is reported once, then moved aside (kept for
// the user as .corrupt) so the next start does not offer it again.
TEST(RecoveryFile, ACorruptRecoveryFileIsReportedOnceThenMovedAside) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/recovery-999999998.kinema", "{\"format\": \"kinema\", \"version\": 1, \"skel");
  test::writeFile(dir + "/recovery-999999998.json", "{\"original\": \"/tmp/walk.kinema\", \"pid\": 999999998, \"time\": 5}");
  std::optional<RecoverableSession> s = findRecoverableSession(dir);
  ASSERT_TRUE(s.has_value());
  Autosaver saver(dir);
  Result<Document> doc = recover(*s, saver);
  ASSERT_FALSE(doc.ok());
  const std::string aside = dir + "/recovery-999999998.kinema.corrupt";
  EXPECT_NE(doc.error().find("recovery-999999998.kinema"), std::string::npos) << doc.error();
  EXPECT_NE(doc.error().find("moved aside to " + aside + ", not offered again"), std::string::npos) << doc.error();
  EXPECT_EQ(doc.error().find('\n'), std::string::npos);
  EXPECT_TRUE(fs::exists(aside));  // the bytes are kept for the user
  EXPECT_EQ(test::readFile(aside), "{\"format\": \"kinema\", \"version\": 1, \"skel");
  EXPECT_FALSE(fs::exists(dir + "/recovery-999999998.kinema"));
  EXPECT_FALSE(fs::exists(dir + "/recovery-999999998.json"));
  std::string message;
  EXPECT_FALSE(findRecoverableSession(dir, &message).has_value());  // not offered (or reported) again
  EXPECT_EQ(message, "");
  EXPECT_FALSE(fs::exists(saver.recoveryPath()));  // nothing of ours was written for it
  fs::remove_all(dir);
}

TEST(RecoveryFile, AKilledSessionIsRecoveredWithItsEdit) {
  const std::string dir = test::makeTempDir();
  const std::string original = dir + "/work.kinema";
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The crashing editor: open, edit, autosave, then hang until killed.
    close(ready[0]);
    Document doc = newDocument();
    doc.setPath(original);
    Autosaver saver(dir, 60.0);
    saver.tick(doc, 0.0);
    char ok = setJointRotation(doc, doc.skeleton().find("LowerArm.L"), kEdit).empty() &&
                      saver.tick(doc, 61.0).empty() && fs::exists(saver.recoveryPath())
                  ? '1'
                  : '0';
    if (write(ready[1], &ok, 1) != 1) _exit(3);
    for (;;) pause();
  }
  close(ready[1]);
  char ok = 0;
  ASSERT_EQ(read(ready[0], &ok, 1), 1);
  close(ready[0]);
  ASSERT_EQ(kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_EQ(ok, '1') << "the child could not edit and autosave";

  std::string message;
  std::optional<RecoverableSession> s = findRecoverableSession(dir, &message);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(message, "");
  EXPECT_EQ(s->pid, static_cast<long>(child));
  EXPECT_EQ(s->originalPath, original);
  Autosaver saver(dir);
  Result<Document> doc = recover(*s, saver);
  ASSERT_TRUE(doc) << doc.error();
  EXPECT_TRUE(doc->dirty());
  EXPECT_EQ(doc->path(), original);
  const int elbow = doc->skeleton().find("LowerArm.L");
  const glm::quat expected = glm::normalize(kEdit);  // what setJointRotation stores
  EXPECT_EQ(std::memcmp(&doc->pose().local[elbow].rotation, &expected, sizeof expected), 0);
  // The files now belong to this process; the dead one's are gone.
  EXPECT_FALSE(fs::exists(s->recoveryPath));
  EXPECT_TRUE(fs::exists(saver.recoveryPath()));
  EXPECT_FALSE(findRecoverableSession(dir).has_value());
  saver.removeFiles();
  EXPECT_FALSE(fs::exists(saver.recoveryPath()));
  fs::remove_all(dir);
}

TEST(RecoveryFile, StateDirFollowsXdg) {
  const char* old = std::getenv("XDG_STATE_HOME");
  const std::string saved = old ? old : "";
  setenv("XDG_STATE_HOME", "/tmp/xdg-state", 1);
  EXPECT_EQ(defaultRecoveryDir(), "/tmp/xdg-state/kinema/recovery");
  unsetenv("XDG_STATE_HOME");
  const char* home = std::getenv("HOME");
  if (home) {
    EXPECT_EQ(defaultRecoveryDir(), std::string(home) + "/.local/state/kinema/recovery");
  }
  if (old) setenv("XDG_STATE_HOME", saved.c_str(), 1);
}

}  // namespace
}  // namespace kinema
