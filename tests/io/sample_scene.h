#pragma once
// A small scene that uses every part of the data model glTF can carry: two roots, a
// chain of eight skinned joints (eight influences per vertex), morph targets with
// names, a textured material, a node order that differs from the joint order, and
// clips with every interpolation family (some exact in glTF, some not).
#include "scene/scene.h"

namespace kinema::test {

Scene makeSampleScene();

// Joint indices in makeSampleScene().
enum SampleJoint { kRoot = 0, kB1, kB2, kB3, kB4, kB5, kB6, kB7, kBody };

}  // namespace kinema::test
