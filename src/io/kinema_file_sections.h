#pragma once
// The .kinema file's sections (docs/kinema-format.md), each read and written in its own file
// beside the other: io/kinema_file_skeleton.cpp, _clips, _ik, _simulation and _assets.
// io/kinema_file.cpp puts them together. Readers take the whole JSON tree (`root`) and fill
// their part of the scene; they return false with the reason in the Reader.
#include <string>

#include "io/kinema_format_reader.h"
#include "scene/scene.h"

namespace kinema::kinema_format {

// "skeleton" (required): joints in parent-before-child order, with rest transforms.
bool readSkeleton(Reader& r, const Json& root, Skeleton& s);
Json skeletonToJson(const Skeleton& s);
// "pose" (optional): the editor's working pose; a joint left out keeps its rest transform.
bool readPose(Reader& r, const Json& root, Scene& scene);
Json poseToJson(const Scene& scene);

// "clips" (optional): needs the skeleton read first.
bool readClips(Reader& r, const Json& root, Scene& scene);
Json clipsToJson(const Scene& scene);

// "ik" (optional): joint limits and saved targets. readIkObject reads the object found at
// JSON path `at` (also an IK rig file's top level, with `at` empty).
bool readIk(Reader& r, const Json& root, Scene& scene);
bool readIkObject(Reader& r, const Json& ik, const std::string& at, Scene& scene);
Json ikToJson(const Scene& scene);

// "simulation" (optional): dynamic chains, ragdolls, crowds and particle systems.
bool readSimulation(Reader& r, const Json& root, Scene& scene);
Json simulationToJson(const Scene& scene);

// "node_of_joint", "node_names", "images", "materials", "meshes", "skins", "mesh_instances"
// (optional: glTF scenes). sceneAssetsError says what saving must refuse: references the
// file could not express or read back.
bool readSceneAssets(Reader& r, const Json& root, Scene& scene);
void sceneAssetsToJson(const Scene& scene, Json& root);
std::string sceneAssetsError(const Scene& scene);

}  // namespace kinema::kinema_format
