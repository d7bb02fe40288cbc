// Issue 19 (h19cli): numbers a file or an argument makes too large for float, and the CLI
// options around them, through the built binary: non-finite results end in one line naming
// the joint and the file (exit 1, nothing on stdout); IK targets in double; --up z for Z-up
// BVH; render --frames past the clip's end; --size against the GL's own limit; the dashed
// relationship line to a joint that moves on its own. Every file is written by the test.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>

#include <nlohmann/json.hpp>

#include "io/image.h"
#include "render/camera.h"
#include "render/image_compare.h"
#include "render/skeleton_view.h"
#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using Json = nlohmann::json;

// Rendering forced onto llvmpipe (as the other render tests) so pixels do not depend on a GPU.
const std::string kSoftware =
    "LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";

struct CommandRun {
  int code = -1;
  std::string out, err;
};

CommandRun kinema(const std::string& args) {
  CommandRun r;
  r.code = runCommand(kSoftware + KINEMA_BINARY + " " + args, &r.out, &r.err);
  return r;
}

int lineCount(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// A chain Root -> J1 -> J2 -> J3 (+ End Site) whose joints sit `offset` apart along X.
std::string chainBvh(const std::string& offset) {
  std::string s = "HIERARCHY\nROOT Root\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  std::string close;
  for (int i = 1; i <= 3; ++i) {
    s += "JOINT J" + std::to_string(i) + "\n{\n  OFFSET " + offset + " 0 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n";
    close += "}\n";
  }
  s += "End Site\n{\n  OFFSET 0 1 0\n}\n" + close + "}\nMOTION\nFrames: 2\nFrame Time: 0.0333333\n";
  for (int f = 0; f < 2; ++f) s += "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n";
  return s;
}

// Nodes N0 -> N1 -> N2 -> N3, each scaled by 1e30: N1's world scale is 1e60, past float.
std::string scaledChainGltf() {
  Json nodes = Json::array();
  for (int i = 0; i < 4; ++i) {
    Json n = {{"name", "N" + std::to_string(i)}, {"scale", {1e30, 1e30, 1e30}}, {"translation", {0.0, 1.0, 0.0}}};
    if (i < 3) n["children"] = {i + 1};
    nodes.push_back(n);
  }
  Json gltf = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", {0}}}}}, {"nodes", nodes}};
  return gltf.dump();
}

class HostileNumbersCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = makeTempDir(); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
  std::string dir_;
};

// The contract for a result that is not finite: exit 1, nothing on stdout (no JSON null),
// one line on stderr naming the file and the joint where the chain overflows.
void expectNonFiniteError(const CommandRun& r, const std::string& file, const std::string& joint, const std::string& what) {
  EXPECT_EQ(r.code, 1) << what << "\n" << r.out << r.err;
  EXPECT_TRUE(r.out.empty()) << what << ": " << r.out.substr(0, 300);
  EXPECT_EQ(lineCount(r.err), 1) << what << ": " << r.err;
  EXPECT_NE(r.err.find(file), std::string::npos) << what << ": " << r.err;
  EXPECT_NE(r.err.find("joint '" + joint + "'"), std::string::npos) << what << ": " << r.err;
  EXPECT_NE(r.err.find("not finite"), std::string::npos) << what << ": " << r.err;
  EXPECT_LE(r.err.size(), 301u) << what;
}

TEST_F(HostileNumbersCli, ChainsThatOverflowFloatEndInOneLineNamingTheJointAndTheFile) {
  // 3e38 + 3e38 > FLT_MAX: J1 is finite, J2 is the first joint out of float's range.
  const std::string bvh = path("overflow.bvh"), kin = path("overflow.kinema"), gltf = path("scaled.gltf");
  writeFile(bvh, chainBvh("3e38"));
  writeFile(gltf, scaledChainGltf());
  // The file itself holds finite numbers only, so it converts; evaluating it does not.
  ASSERT_EQ(kinema("convert " + bvh + " " + kin).code, 0);
  const struct {
    std::string file, joint, effector;
  } cases[] = {{bvh, "J2", "J3"}, {kin, "J2", "J3"}, {gltf, "N1", "N3"}};
  for (const auto& c : cases) {
    expectNonFiniteError(kinema("pose " + c.file + " --frame 0 --json"), c.file, c.joint, "pose --json " + c.file);
    expectNonFiniteError(kinema("pose " + c.file + " --frame 0"), c.file, c.joint, "pose " + c.file);
    expectNonFiniteError(kinema("ik " + c.file + " --effector " + c.effector + " --target 0,1,0 --json"), c.file,
                         c.joint, "ik " + c.file);
    expectNonFiniteError(kinema("skin " + c.file + " --json"), c.file, c.joint, "skin " + c.file);
    expectNonFiniteError(kinema("render " + c.file + " --size 64x48 --out " + path("never.png")), c.file, c.joint,
                         "render " + c.file);
  }
  EXPECT_FALSE(std::filesystem::exists(path("never.png")));
  // The same chain with offsets float holds stays fine (the check is not a blanket refusal).
  const std::string ok = path("ok.bvh");
  writeFile(ok, chainBvh("1e37"));
  const CommandRun r = kinema("pose " + ok + " --frame 0 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.find("null"), std::string::npos);
  EXPECT_FLOAT_EQ(Json::parse(r.out)["joints"][3]["world"][12].get<float>(), 3e37f);
}

TEST_F(HostileNumbersCli, IkTargetsBeyond1e18AreBadInputAndErrorsAreDoubles) {
  const std::string bvh = path("arm.bvh");
  writeFile(bvh, chainBvh("1"));  // reach 3 from the root
  for (const char* solver : {"fabrik", "ccd", "jacobian-dls", "two-bone"}) {
    const CommandRun far = kinema("ik " + bvh + " --solver " + solver + " --effector J3 --target 2e19,0,0 --json");
    EXPECT_EQ(far.code, 1) << solver << far.err;
    EXPECT_TRUE(far.out.empty()) << solver;
    EXPECT_EQ(lineCount(far.err), 1) << far.err;
    EXPECT_NE(far.err.find("1e18"), std::string::npos) << far.err;
    // 1e17 away: out of reach, so the error is the distance from the stretched arm's end,
    // 1e17 - 3 (the chain points at the target), finite and computed in double.
    const CommandRun near = kinema("ik " + bvh + " --solver " + solver + " --effector J3 --target 1e17,0,0 --json");
    ASSERT_EQ(near.code, 0) << solver << near.err;
    const Json j = Json::parse(near.out);
    ASSERT_TRUE(j["error"].is_number()) << solver << " " << j["error"];
    EXPECT_NEAR(j["error"].get<double>(), 1e17, 1e17 * 1e-6) << solver;
    EXPECT_FALSE(j["converged"].get<bool>()) << solver;
  }
  // The pole counts too; a denormal coordinate is a number (exit 0), 1e400 is not finite.
  EXPECT_EQ(kinema("ik " + bvh + " --solver two-bone --effector J3 --target 1,1,0 --pole 0,0,5e18").code, 1);
  const CommandRun tiny = kinema("ik " + bvh + " --effector J3 --target 1e-310,0,0 --json");
  EXPECT_EQ(tiny.code, 0) << tiny.err;
  const CommandRun huge = kinema("ik " + bvh + " --effector J3 --target 1e400,0,0 --json");
  EXPECT_EQ(huge.code, 1) << huge.err;
  EXPECT_NE(huge.err.find("finite"), std::string::npos) << huge.err;
}

// A small character twice: Y-up, and the same written Z-up as Blender's BVH exporter does
// ((x, y, z) -> (x, -z, y), a yaw about Y becomes one about Z), with a pose that moves the
// root, turns it and bends the knee.
std::string character(bool zUp) {
  const auto off = [zUp](double x, double y, double z) {
    char b[96];
    std::snprintf(b, sizeof b, "%g %g %g", x, zUp ? -z : y, zUp ? y : z);
    return std::string(b);
  };
  std::string s = "HIERARCHY\nROOT Hips\n{\n  OFFSET " + off(0, 0.9, 0) +
                  "\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  s += "  JOINT Knee\n  {\n    OFFSET " + off(0.1, -0.45, 0) + "\n    CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "    JOINT Foot\n    {\n      OFFSET " + off(0, -0.45, 0) + "\n      CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "      End Site\n      {\n        OFFSET " + off(0, 0, 0.15) + "\n      }\n    }\n  }\n";
  s += "  JOINT Head\n  {\n    OFFSET " + off(0, 0.7, 0) + "\n    CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "    End Site\n    {\n      OFFSET " + off(0, 0.2, 0) + "\n    }\n  }\n}\n";
  s += "MOTION\nFrames: 2\nFrame Time: 0.0333333\n";
  const std::string turn = zUp ? "30 0 0" : "0 0 30";  // Zrotation Xrotation Yrotation
  s += off(0, 0.9, 0) + " 0 0 0 0 0 0 0 0 0 0 0 0\n";
  s += off(0.2, 0.9, 0.3) + " " + turn + " 0 40 0 0 -20 0 0 0 0\n";
  return s;
}

std::vector<glm::vec3> positions(const Json& pose) {
  std::vector<glm::vec3> out;
  for (const Json& j : pose["joints"])
    out.emplace_back(j["world"][12].get<float>(), j["world"][13].get<float>(), j["world"][14].get<float>());
  return out;
}

TEST_F(HostileNumbersCli, UpZReadsAZUpBvhStandingOnItsFeet) {
  const std::string yup = path("yup.bvh"), zup = path("zup.bvh");
  writeFile(yup, character(false));
  writeFile(zup, character(true));
  for (const char* frame : {"0", "1"}) {
    const CommandRun want = kinema("pose " + yup + " --frame " + frame + " --json");
    const CommandRun got = kinema("pose " + zup + " --up z --frame " + frame + " --json");
    ASSERT_EQ(got.code, 0) << got.err;
    const std::vector<glm::vec3> a = positions(Json::parse(want.out)), b = positions(Json::parse(got.out));
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_VEC3_NEAR(b[i], a[i], 1e-5f);
    // Feet on the ground, the head above them along +Y.
    EXPECT_NEAR(b[2].y, frame[0] == '0' ? 0.0f : b[2].y, 1e-5f);
    EXPECT_GT(b[5].y, 1.7f);
  }
  // Read as Y-up (the default), the same file lies on its back: height along +Z.
  const std::vector<glm::vec3> lying = positions(Json::parse(kinema("pose " + zup + " --frame 0 --json").out));
  EXPECT_NEAR(lying[5].z, 1.8f, 1e-5f);
  EXPECT_NEAR(lying[5].y, 0.0f, 1e-5f);

  // Every command that reads BVH takes it: ik moves the same joint to the same place,
  // convert writes a Y-up file equal to the Y-up original, render and skin accept it.
  const std::string ik = " --frame 1 --effector Foot --root Hips --target 0.3,0.1,0.5 --solver ccd --json";
  const std::vector<glm::vec3> ikY = positions(Json::parse(kinema("ik " + yup + ik).out));
  const CommandRun ikZ = kinema("ik " + zup + " --up z" + ik);
  ASSERT_EQ(ikZ.code, 0) << ikZ.err;
  const std::vector<glm::vec3> ikZp = positions(Json::parse(ikZ.out));
  for (size_t i = 0; i < ikY.size(); ++i) EXPECT_VEC3_NEAR(ikZp[i], ikY[i], 1e-4f);
  ASSERT_EQ(kinema("convert " + zup + " " + path("back.bvh") + " --up z").code, 0);
  const std::vector<glm::vec3> back = positions(Json::parse(kinema("pose " + path("back.bvh") + " --frame 1 --json").out));
  const std::vector<glm::vec3> want = positions(Json::parse(kinema("pose " + yup + " --frame 1 --json").out));
  for (size_t i = 0; i < want.size(); ++i) EXPECT_VEC3_NEAR(back[i], want[i], 1e-4f);
  EXPECT_EQ(kinema("render " + zup + " --up z --size 64x48 --out " + path("z.png")).code, 0);
  EXPECT_EQ(kinema("skin " + zup + " --up z --json").code, 0);
  EXPECT_EQ(kinema("edit --help").out.find("--up") != std::string::npos, true);
  EXPECT_EQ(kinema("pose " + zup + " --up x --frame 0").code, 2);  // not an axis: usage
}

TEST_F(HostileNumbersCli, RenderFramesStopAtTheClipsLastFrameWithAWarning) {
  const std::string bvh = path("three.bvh");
  std::string text = character(false);
  text.replace(text.find("Frames: 2"), 9, "Frames: 3");
  text += "0 0.9 0 0 0 0 0 10 0 0 0 0 0 0 0\n";
  writeFile(bvh, text);  // frames 0, 1, 2
  const CommandRun r = kinema("render " + bvh + " --frames 1:100000 --size 48x32 --out " + path("seq/f_%06d.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(path("seq/f_000001.png")));
  EXPECT_TRUE(std::filesystem::exists(path("seq/f_000002.png")));
  EXPECT_FALSE(std::filesystem::exists(path("seq/f_000003.png")));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(path("seq")), std::filesystem::directory_iterator()), 2);
  EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("last frame, 2"), std::string::npos) << r.err;
  // A range that starts after the end has nothing to show.
  const CommandRun after = kinema("render " + bvh + " --frames 5:9 --size 48x32 --out " + path("late/f_%d.png"));
  EXPECT_EQ(after.code, 1);
  EXPECT_EQ(lineCount(after.err), 1) << after.err;
  EXPECT_FALSE(std::filesystem::exists(path("late")));
}

TEST_F(HostileNumbersCli, SizeBeyondTheGlLimitIsRefusedWithTheLimit) {
  const CommandRun r = kinema("render --size 100000x64 --out " + path("wide.png"));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  std::smatch m;
  const std::string err = r.err;
  ASSERT_TRUE(std::regex_search(err, m, std::regex("largest image .* is ([0-9]+)x([0-9]+) \\(GL_MAX_"))) << r.err;
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  EXPECT_GE(w, 1024);  // OpenGL 3.3 guarantees at least 1024 for each of the three limits
  EXPECT_LT(w, 100000);
  EXPECT_GE(h, 1024);
  EXPECT_FALSE(std::filesystem::exists(path("wide.png")));
  // A size past the limit in one direction only is refused the same way.
  const CommandRun tall = kinema("render --size 64x" + std::to_string(h + 1) + " --out " + path("tall.png"));
  EXPECT_EQ(tall.code, 1);
  EXPECT_NE(tall.err.find(std::to_string(w) + "x" + std::to_string(h)), std::string::npos) << tall.err;
}

// A root placed away from the origin with the hips a metre off it: `walk` gives the hips
// their own position channels (they move on their own, as a walk's hips do), otherwise they
// only rotate. Rest geometry is the same.
std::string rootAndHips(bool walk) {
  std::string s = "HIERARCHY\nROOT Root\n{\n  OFFSET -0.8 0.3 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "  JOINT Hips\n  {\n    OFFSET 0.8 0.7 0\n    CHANNELS ";
  s += walk ? "6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n" : "3 Zrotation Xrotation Yrotation\n";
  s += "    JOINT Spine\n    {\n      OFFSET 0 0.5 0\n      CHANNELS 3 Zrotation Xrotation Yrotation\n";
  s += "      End Site\n      {\n        OFFSET 0 0.4 0\n      }\n    }\n  }\n}\nMOTION\nFrames: 2\nFrame Time: 0.0333333\n";
  for (int f = 0; f < 2; ++f) s += walk ? "0 0 0 " + std::to_string(0.8 + 0.1 * f) + " 0.7 0 0 0 0 0 0 0\n" : "0 0 0 0 0 0 0 0 0\n";
  return s;
}

// The pixel of a world point in a W x H image through the camera `kinema render --camera
// AZ,EL` uses (defaultCamera framing the joints, the angles replaced).
glm::vec2 project(const glm::vec3& p, const std::vector<glm::vec3>& joints, float az, float el, int w, int h) {
  Bounds b;
  for (const glm::vec3& j : joints) b.add(j);
  OrbitCamera cam = defaultCamera(b, float(w) / float(h));
  cam.azimuthDeg = az;
  cam.elevationDeg = el;
  cam.fitClipPlanes(b.radius());
  const glm::vec4 c = cam.projection(float(w) / float(h)) * cam.view() * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(c) / c.w;
  return {(ndc.x * 0.5f + 0.5f) * w, (0.5f - ndc.y * 0.5f) * h};
}

// Whether any pixel within one of (x, y) is lit like a bone or a relationship line (the
// background is 60/255 grey, the grid darker than 120).
bool litNear(const Image& im, glm::vec2 at) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = int(std::lround(at.x)) + dx, y = int(std::lround(at.y)) + dy;
      if (x < 0 || y < 0 || x >= im.width || y >= im.height) continue;
      const std::uint8_t* p = im.pixel(x, y);
      if (p[0] > 140 && p[1] > 140 && p[2] > 140) return true;
    }
  return false;
}

TEST_F(HostileNumbersCli, AJointMovingOnItsOwnHangsOnADashedRelationshipLine) {
  constexpr int kW = 480, kH = 360;
  std::vector<bool> lit[2];
  for (int walk = 0; walk < 2; ++walk) {
    const std::string bvh = path(walk ? "walk.bvh" : "still.bvh"), png = path(walk ? "walk.png" : "still.png");
    writeFile(bvh, rootAndHips(walk != 0));
    const CommandRun r = kinema("render " + bvh + " --frame 0 --camera 0,0 --size " + std::to_string(kW) + "x" +
                         std::to_string(kH) + " --out " + png);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::vector<glm::vec3> joints = positions(Json::parse(kinema("pose " + bvh + " --frame 0 --json").out));
    const Image im = loadImageOrFail(png);
    ASSERT_EQ(im.width, kW);
    const glm::vec2 root = project(joints[0], joints, 0, 0, kW, kH), hips = project(joints[1], joints, 0, 0, kW, kH);
    ASSERT_GT(glm::length(hips - root), 100.0f);
    // Samples one pixel apart along the middle 60% of root -> hips (clear of the spheres).
    const float n = glm::length(hips - root);
    for (float s = 0.2f * n; s <= 0.8f * n; s += 1.0f) lit[walk].push_back(litNear(im, root + (hips - root) * (s / n)));
  }
  const auto fraction = [](const std::vector<bool>& v) { return double(std::count(v.begin(), v.end(), true)) / v.size(); };
  const auto switches = [](const std::vector<bool>& v) {
    int n = 0;
    for (size_t i = 1; i < v.size(); ++i) n += v[i] != v[i - 1];
    return n;
  };
  // Only rotating: a solid bone covers the whole way.
  EXPECT_GT(fraction(lit[0]), 0.97) << "still";
  // Moving on its own: dashes, lit and unlit in turn, many times along the line.
  EXPECT_GT(fraction(lit[1]), 0.3) << "walk";
  EXPECT_LT(fraction(lit[1]), 0.85) << "walk";
  EXPECT_GE(switches(lit[1]), 12) << "walk";
}

TEST_F(HostileNumbersCli, XRayWithoutMeshesShowsTheGridThroughTheBones) {
  const std::string bvh = path("still.bvh");
  writeFile(bvh, rootAndHips(false));
  const std::string common = "render " + bvh + " --frame 0 --camera 20,10 --size 160x120 --out ";
  ASSERT_EQ(kinema(common + path("on.png")).code, 0);
  ASSERT_EQ(kinema(common + path("xray.png") + " --bones xray").code, 0);
  const Image on = loadImageOrFail(path("on.png")), xray = loadImageOrFail(path("xray.png"));
  // The x-ray bones are the translucent blue of SkeletonStyle::xRay(), not the grey bones.
  int blue = 0, grey = 0;
  for (int y = 0; y < xray.height; ++y)
    for (int x = 0; x < xray.width; ++x) {
      const std::uint8_t* p = xray.pixel(x, y);
      blue += p[2] > p[0] + 40;
      const std::uint8_t* q = on.pixel(x, y);
      grey += q[0] > 140 && std::abs(int(q[0]) - int(q[2])) < 12;
    }
  EXPECT_GT(blue, 100);
  EXPECT_GT(grey, 100);
  EXPECT_GT(differingPixels(on, xray, 24), 100);
}

}  // namespace
}  // namespace kinema::test
