// assets/ is made by the project's own code (target update-assets); it must stay in sync.
#include "core/default_character.h"
#include "io/kinema_file.h"
#include "scene/default_character_scene.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(Assets, DefaultCharacterFileIsWhatTheCodeMakes) {
  const std::string path = std::string(KINEMA_SOURCE_DIR) + "/assets/default_character.kinema";
  Result<Scene> loaded = loadKinemaFile(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  const Skeleton made = makeDefaultCharacter();
  EXPECT_EQ(loaded->skeleton.names, made.names);
  EXPECT_EQ(loaded->skeleton.parents, made.parents);
  EXPECT_EQ(loaded->skeleton.rest, made.rest);
  EXPECT_TRUE(loaded->clips.empty());
  EXPECT_EQ(loaded->meshes.size(), 1u) << "the skinned body";
  EXPECT_EQ(readFile(path), toKinemaJson(makeDefaultCharacterScene()))
      << "assets/default_character.kinema is stale: run `cmake --build build --target update-assets`";
}

}  // namespace
}  // namespace kinema::test
