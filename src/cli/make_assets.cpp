// Writes the files in assets/ from the project's own code:
//   make_assets ASSETS_DIR
// (build target `update-assets`; a test checks the committed files match).
#include <cstdio>

#include "scene/default_character_scene.h"
#include "io/kinema_file.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_assets ASSETS_DIR\n");
    return 2;
  }
  const kinema::Scene scene = kinema::makeDefaultCharacterScene();
  const std::string path = std::string(argv[1]) + "/default_character.kinema";
  const std::string error = kinema::saveKinemaFile(path, scene);
  if (!error.empty()) {
    std::fprintf(stderr, "make_assets: %s\n", error.c_str());
    return 1;
  }
  std::printf("wrote %s\n", path.c_str());
  return 0;
}
