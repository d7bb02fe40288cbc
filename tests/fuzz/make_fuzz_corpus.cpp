// Writes the fuzz seed corpus from the project's own code: small valid BVH files of every
// shape the reader supports, .kinema files made by the writer, and binary clip inputs.
//   make_fuzz_corpus OUT_DIR   (creates OUT_DIR/bvh, OUT_DIR/kinema, OUT_DIR/sampling, OUT_DIR/ik)
#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "core/default_character.h"
#include "io/bvh.h"
#include "io/kinema_file.h"
#include "io/gltf_test_files.h"

namespace {

void write(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f << bytes;
}

std::string bvhWithOrder(const char* order, bool crlf, bool tabs) {
  std::string r;
  auto line = [&](std::string s) {
    if (tabs)
      for (char& c : s)
        if (c == ' ') c = '\t';
    r += s + (crlf ? "\r\n" : "\n");
  };
  const std::string rot = std::string(1, order[0]) + "rotation " + order[1] + "rotation " + order[2] + "rotation";
  line("HIERARCHY");
  line("ROOT Hips");
  line("{");
  line("OFFSET 0 0 0");
  line("CHANNELS 6 Xposition Yposition Zposition " + rot);
  line("JOINT Spine");
  line("{");
  line("OFFSET 0 1.5 0");
  line("CHANNELS 3 " + rot);
  line("End Site");
  line("{");
  line("OFFSET 0 .5 0");
  line("}");
  line("}");
  line("JOINT Leg");
  line("{");
  line("OFFSET 0.2 -1 0");
  line("CHANNELS 6 Xposition Yposition Zposition " + rot);
  line("End Site");
  line("{");
  line("OFFSET 0 -1 0");
  line("}");
  line("}");
  line("}");
  line("MOTION");
  line("Frames: 3");
  line("Frame Time: .0333333");
  line("0 1 0 10 20 30 5 -5 15 0.2 -1 0 1 2 3");
  line("0.1 1 0 -10 45 90 0 0 0 0.2 -1.1 0 -90 0 90");
  line("0.2 1.1 -0.1 180 -45 0.5 1e-3 2.5E1 -0 0.2 -1 0 0 0 0");
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_fuzz_corpus OUT_DIR\n");
    return 2;
  }
  const std::string out = argv[1];
  for (const char* sub : {"", "/bvh", "/kinema", "/sampling", "/ik", "/gltf", "/script", "/ik_args"}) ::mkdir((out + sub).c_str(), 0755);

  const char* orders[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};
  int n = 0;
  for (const char* o : orders) {
    write(out + "/bvh/order_" + o + ".bvh", bvhWithOrder(o, n % 2 == 1, n % 3 == 2));
    ++n;
  }
  write(out + "/bvh/two_roots.bvh",
        "HIERARCHY\nROOT A\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n}\n"
        "ROOT B\n{\nOFFSET 1 0 0\nCHANNELS 1 Yrotation\nEnd Site\n{\nOFFSET 0 1 0\n}\n}\n"
        "MOTION\nFrames: 2\nFrame Time: 0.5\n0 0 0 0\n90 0 0 45\n");
  write(out + "/bvh/no_frames.bvh",
        "HIERARCHY\nROOT A {\nOFFSET 0 0 0\nCHANNELS 0\n}\nMOTION\nFrames: 0\nFrame Time: 1\n");

  // glTF: a small animated file as .gltf and .glb, and a skinned, morphing triangle.
  {
    const kinema::test::GltfTestFile animated = kinema::test::smallAnimatedFile();
    write(out + "/gltf/animated.gltf", animated.gltf());
    write(out + "/gltf/animated.glb", animated.glb());
    kinema::test::GltfTestFile f = kinema::test::smallAnimatedFile();
    const int pos = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    const int joints = f.addInts(std::vector<std::uint8_t>{0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}, kinema::test::kGltfUByte, "VEC4", 3);
    const int weights = f.addFloats({0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 0.25f, 0.75f, 0, 0}, "VEC4");
    const int delta = f.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3");
    const int idx = f.addInts(std::vector<std::uint16_t>{0, 1, 2}, kinema::test::kGltfUShort, "SCALAR", 3);
    f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", pos}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}},
                                         {"indices", idx}, {"targets", {{{"POSITION", delta}}}}}}},
                        {"weights", {0.5}}}};
    f.addNode({{"mesh", 0}, {"skin", 0}});
    f.doc["skins"] = {{{"joints", {0, 1}}}};
    write(out + "/gltf/skinned.gltf", f.gltf());
    write(out + "/gltf/skinned.glb", f.glb());
  }

  // Editor input scripts (kinema edit --script): JSON lines and a JSON array, every event type.
  write(out + "/script/rotate.jsonl",
        "# R Z 45 on a clicked joint\n"
        "{\"frame\": 1, \"type\": \"key\", \"key\": \"KP_1\"}\n"
        "{\"frame\": 2, \"type\": \"mouse_move\", \"x\": 700, \"y\": 236}\n"
        "{\"frame\": 3, \"type\": \"click\", \"button\": \"left\", \"mods\": [\"shift\"]}\n"
        "{\"frame\": 5, \"type\": \"key\", \"key\": \"R\"}\n"
        "{\"frame\": 6, \"type\": \"text\", \"text\": \"45\"}\n"
        "{\"frame\": 7, \"type\": \"scroll\", \"x\": 0, \"y\": -1}\n");
  write(out + "/script/drag.json",
        "[{\"frame\": 1, \"type\": \"button_down\", \"button\": \"middle\"},"
        " {\"frame\": 2, \"type\": \"mouse_move\", \"x\": 10.5, \"y\": 20},"
        " {\"frame\": 3, \"type\": \"button_up\", \"button\": \"middle\"},"
        " {\"frame\": 4, \"type\": \"key_down\", \"key\": \"LEFT_CONTROL\"},"
        " {\"frame\": 4, \"type\": \"key_up\", \"key\": \"LEFT_CONTROL\"}]\n");

  // .kinema files written by the project's writer.
  kinema::Scene character;
  character.skeleton = kinema::makeDefaultCharacter();
  write(out + "/kinema/default_character.kinema", kinema::toKinemaJson(character));
  kinema::Result<kinema::BvhData> bvh = kinema::parseBvh(bvhWithOrder("ZXY", false, false), "seed.bvh");
  if (bvh.ok()) {
    kinema::Scene scene;
    scene.skeleton = bvh->skeleton();
    scene.clips.push_back(bvh->clip());
    scene.clips.back().channels.front().interpolation = kinema::Interpolation::Step;
    write(out + "/kinema/from_bvh.kinema", kinema::toKinemaJson(scene));
  }

  // Clip-sampling inputs: [target][interpolation] then (time, x, y, z, w) per key, then a time.
  auto clipInput = [&](const std::string& name, std::uint8_t target, std::uint8_t interp,
                       const std::vector<float>& floats) {
    std::string bytes{static_cast<char>(target), static_cast<char>(interp)};
    bytes.append(reinterpret_cast<const char*>(floats.data()), floats.size() * sizeof(float));
    write(out + "/sampling/" + name, bytes);
  };
  clipInput("rotation_linear", 1, 1, {0, 0, 0, 0, 1, 1, 0, 0.7071f, 0, 0.7071f, 0.5f});
  clipInput("translation_step", 0, 0, {0, 1, 2, 3, 0, 2, -1, 0, 5, 0, 1.5f});
  clipInput("scale_linear_three_keys", 2, 1, {0, 1, 1, 1, 0, 1, 2, 2, 2, 0, 3, 1, 1, 1, 0, 2.9f});
  // IK inputs (fuzz_ik): [solver][joints - 2][flags], then per joint an offset (x, y, z),
  // per joint a rotation (x, y, z, w), the target (x, y, z), and [max iterations].
  for (std::uint8_t solver = 0; solver < 6; ++solver) {
    for (std::uint8_t flags : {std::uint8_t(0), std::uint8_t(1)}) {  // a chain; a branch at joint 1
      std::string bytes{static_cast<char>(solver), 2, static_cast<char>(flags)};
      std::vector<float> floats;
      for (int j = 0; j < 4; ++j) floats.insert(floats.end(), {0.0f, j ? 1.0f : 0.0f, 0.0f});
      for (int j = 0; j < 4; ++j) floats.insert(floats.end(), {0.0f, 0.0f, 0.38268343f, 0.9238795f});
      floats.insert(floats.end(), {1.2f, 1.5f, 0.3f});
      bytes.append(reinterpret_cast<const char*>(floats.data()), floats.size() * sizeof(float));
      bytes += static_cast<char>(20);
      write(out + "/ik/solver" + std::to_string(solver) + (flags ? "_branch" : "_chain"), bytes);
    }
  }
  // `kinema ik` arguments after the file (fuzz_ik_args), NUL-separated, on the default character.
  auto ikArgs = [&](const std::string& name, const std::vector<std::string>& args) {
    std::string bytes;
    for (size_t i = 0; i < args.size(); ++i) bytes += (i ? std::string(1, '\0') : "") + args[i];
    write(out + "/ik_args/" + name, bytes);
  };
  ikArgs("fabrik_json", {"--effector", "Hand.L", "--target", "0.5,1.2,0.3", "--json"});
  ikArgs("two_bone_pole", {"--effector", "Hand.L", "--target", "0.5,1.2,0.3", "--solver", "two-bone", "--pole",
                           "0,1.4,-1", "--soften", "0.01", "--json"});
  ikArgs("two_targets_dls", {"--effector", "Hand.L", "--target", "0.5,1.2,0.3", "--effector", "Foot.R", "--target",
                             "-0.1,0.1,0.2", "--root", "Hips", "--root", "Hips", "--solver", "jacobian-dls", "--lambda",
                             "0.2", "--max-iterations", "50", "--tolerance", "1e-4", "--json"});
  ikArgs("ccd_trace_frame", {"--effector", "Toe.L", "--target", "0.2,0,0.3", "--solver", "ccd", "--frame", "3",
                             "--trace", "--json"});
  ikArgs("summary", {"--effector", "HeadTop", "--target", "0,1.9,0.2", "--solver", "jacobian-sdls", "--time", "0.5"});
  std::printf("wrote the fuzz corpus under %s\n", out.c_str());
  return 0;
}
