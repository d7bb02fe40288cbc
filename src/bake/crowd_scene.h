#pragma once
// A crowd with its character: loading the character a crowd names, baking every member, and
// the crowd as one scene of many skinned characters (glTF export).
#include <string>
#include <vector>

#include "io/input_limits.h"
#include "scene/scene.h"
#include "sim/crowd.h"

namespace kinema {

// The character `crowd` names: its file, relative to the folder of `ownSource` (the .kinema
// file that holds the crowd), or a copy of `own` when the crowd names none. Fails when the
// file does not load or has no clip `crowd.clip`.
Result<Scene> loadCrowdCharacter(const CrowdSettings& crowd, const Scene& own, const std::string& ownSource,
                                 const InputLimits& limits = {});

struct CrowdBake {
  CrowdClipMotion motion;
  CrowdRun run;               // frames 0..last
  std::vector<Clip> clips;    // one per member, named crowdMemberName(), keys at frames first..last
};
// Runs the crowd from frame 0 to `last` at the character clip's frame time and bakes frames
// first..last of each member (0 <= first <= last).
Result<CrowdBake> bakeCrowd(const CrowdSettings& crowd, const Scene& character, long long first, long long last);

// Appends the baked crowd to `out` as many characters: member m gets a copy of the character's
// joints named "<member name>/<joint>", its own skin(s) and mesh instances (the meshes,
// materials and images are added once), and its baked keys go into out.clips[0] (made when
// `out` has no clip), retargeted to its joints.
void appendCrowdCharacters(Scene& out, const CrowdSettings& crowd, const Scene& character, const CrowdBake& bake);

// Appends the crowd's obstacles to `out` as plain geometry on a joint of their own,
// "<crowd name>_obstacles" at the origin: each sphere a UV sphere, each box a box, in one
// mesh with one material (sand yellow), so the exported crowd shows what it walks around.
// Nothing when the crowd has no obstacle.
void appendCrowdObstacles(Scene& out, const CrowdSettings& crowd);

}  // namespace kinema
