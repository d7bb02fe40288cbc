#pragma once
// A small skinned glTF built in the test (tests/io/gltf_test_files.h): node 0 "hip" at
// (0, 1, 0) with child node 1 "knee" 1 above it (world (0, 2, 0)); node 2 "body", moved to
// (100, 0, 0), shows mesh 0 through skin 0 = [hip, knee] whose inverse binds undo those
// bind positions. Mesh 0 is one triangle (0, 1, 0), (1, 1, 0), (0, 2, 0) on skin joints
// (0, 1), (0, 1) and (1, 0), with the given WEIGHTS_0 (four per vertex).
#include <vector>

#include "io/gltf_test_files.h"

namespace kinema::test {

// weights: 4 per vertex for the 3 vertices; joints: skin joint 0 or 1 in slots 0 and 1.
inline GltfTestFile skinnedTriangleFile(const std::vector<float>& weights) {
  GltfTestFile f;
  f.addNode({{"name", "hip"}, {"children", {1}}, {"translation", {0, 1, 0}}});
  f.addNode({{"name", "knee"}, {"translation", {0, 1, 0}}});
  f.addNode({{"name", "body"}, {"mesh", 0}, {"skin", 0}, {"translation", {100, 0, 0}}});
  const int pos = f.addFloats({0, 1, 0, 1, 1, 0, 0, 2, 0}, "VEC3");
  f.doc["accessors"][pos]["min"] = {0, 1, 0};
  f.doc["accessors"][pos]["max"] = {1, 2, 0};
  const int joints = f.addInts<uint8_t>({0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0}, kGltfUByte, "VEC4", 3);
  const int w = f.addFloats(weights, "VEC4");
  // Inverse binds: hip at (0, 1, 0), knee at (0, 2, 0) in the bind pose.
  const int ibm = f.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1,  //
                               1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -2, 0, 1},
                              "MAT4");
  f.doc["skins"] = {{{"joints", {0, 1}}, {"inverseBindMatrices", ibm}}};
  nlohmann::json attributes = {{"POSITION", pos}, {"JOINTS_0", joints}, {"WEIGHTS_0", w}};
  nlohmann::json primitive = nlohmann::json::object();
  primitive["attributes"] = attributes;
  nlohmann::json mesh = nlohmann::json::object();
  mesh["primitives"] = nlohmann::json::array({primitive});
  f.doc["meshes"] = nlohmann::json::array({mesh});
  return f;
}

}  // namespace kinema::test
