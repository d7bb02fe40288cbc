#pragma once
// The bone map a clip was retargeted through (File > Import Motion onto Character…, kinema
// retarget): the motion file it came from, its clip, and which of that file's joints drove
// which joint of this skeleton. Kept with the clip so the editor can show and edit the map
// again (.kinema clips[c].bone_map). Source joints are names (that skeleton is not in the
// document); target joints are indices of this skeleton, like channels.
#include <string>
#include <vector>

namespace kinema {

struct SourceMapPair {
  std::string source;  // a joint name of the motion file's skeleton, non-empty
  int target = -1;     // a joint of this skeleton
  bool operator==(const SourceMapPair& o) const { return source == o.source && target == o.target; }
};

struct ClipSourceMap {
  std::string file;  // the motion file as the user named it (may be relative); may be ""
  int clip = 0;      // which clip of that file (>= 0)
  std::vector<SourceMapPair> pairs;  // each source name and target joint at most once

  bool empty() const { return pairs.empty(); }
  bool operator==(const ClipSourceMap& o) const { return file == o.file && clip == o.clip && pairs == o.pairs; }
  bool operator!=(const ClipSourceMap& o) const { return !(*this == o); }
  // "" or what is wrong, for a skeleton of `jointCount` joints.
  std::string validate(int jointCount) const;
};

}  // namespace kinema
