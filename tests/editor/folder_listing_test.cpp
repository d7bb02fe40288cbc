#include "editor/model/folder_listing.h"

#include <cstdlib>

#include <gtest/gtest.h>

#include <filesystem>

#include "editor/panels/editor_panels.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(FolderListing, FoldersFirstThenSupportedFilesSortedHiddenLeftOut) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/walk.BVH", "x");
  writeFile(dir + "/a.kinema", "x");
  writeFile(dir + "/notes.txt", "x");
  writeFile(dir + "/.hidden.bvh", "x");
  writeFile(dir + "/model.glb", "x");
  std::filesystem::create_directory(dir + "/zeta");
  std::filesystem::create_directory(dir + "/alpha");
  std::filesystem::create_directory(dir + "/.git");
  const Result<FolderListing> listing = listFolder(dir + "/zeta/..", openableExtensions());
  ASSERT_TRUE(listing.ok()) << listing.error();
  EXPECT_EQ(listing->folder, std::filesystem::path(dir).lexically_normal().string());
  std::vector<std::string> names;
  for (const FolderEntry& e : listing->entries) names.push_back(e.name + (e.isFolder ? "/" : ""));
  EXPECT_EQ(names, (std::vector<std::string>{"alpha/", "zeta/", "a.kinema", "model.glb", "walk.BVH"}));
  // No filter: every visible file.
  EXPECT_EQ(listFolder(dir, {})->entries.size(), 6u);
  std::filesystem::remove_all(dir);
}

TEST(FolderListing, MissingFolderOrFileIsAnErrorNamingThePath) {
  const std::string dir = makeTempDir();
  const Result<FolderListing> missing = listFolder(dir + "/nope", {});
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find(dir + "/nope"), std::string::npos) << missing.error();
  writeFile(dir + "/f.bvh", "x");
  const Result<FolderListing> file = listFolder(dir + "/f.bvh", {});
  ASSERT_FALSE(file.ok());
  EXPECT_NE(file.error().find("not a folder"), std::string::npos) << file.error();
  std::filesystem::remove_all(dir);
}

TEST(FolderListing, WithExtensionAppendsOnlyWhenMissing) {
  EXPECT_EQ(withExtension("walk", ".kinema"), "walk.kinema");
  EXPECT_EQ(withExtension("walk.KINEMA", ".kinema"), "walk.KINEMA");
  EXPECT_EQ(withExtension("dir.v2/walk", ".glb"), "dir.v2/walk.glb");
  EXPECT_EQ(withExtension("", ".glb"), "");
}

TEST(AutosaveInterval, FromTheEnvironmentWhenAPositiveNumberElseOneMinute) {
  const char* before = std::getenv("KINEMA_AUTOSAVE_SECONDS");
  const std::string saved = before ? before : "";
  const std::pair<const char*, double> cases[] = {
      {"0.25", 0.25}, {"5", 5.0}, {"", 60.0}, {"0", 60.0}, {"-3", 60.0}, {"2s", 60.0}, {"nan", 60.0}, {"1e9", 60.0}};
  for (const auto& [text, expected] : cases) {
    setenv("KINEMA_AUTOSAVE_SECONDS", text, 1);
    EXPECT_EQ(autosaveIntervalSeconds(), expected) << text;
  }
  unsetenv("KINEMA_AUTOSAVE_SECONDS");
  EXPECT_EQ(autosaveIntervalSeconds(), 60.0);
  if (before) setenv("KINEMA_AUTOSAVE_SECONDS", saved.c_str(), 1);
}

}  // namespace
}  // namespace kinema::test
