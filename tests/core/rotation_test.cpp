#include "test_support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "core/rotation.h"

// Euler angles, axis-angle, swing-twist, from-to rotations and slerp, checked against rotation
// matrices written out by hand here (never against the library or glm::angleAxis).

namespace kinema {
namespace KINEMA_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;
const EulerOrder kAllOrders[] = {EulerOrder::XYZ, EulerOrder::XZY, EulerOrder::YXZ,
                                 EulerOrder::YZX, EulerOrder::ZXY, EulerOrder::ZYX};

double deg(double d) { return d * kPi / 180.0; }

// ---- An independent 3x3 matrix in doubles, row-major: m[row][col]. ----
struct M3 {
  std::array<std::array<double, 3>, 3> m{};
};
struct V3 {
  double x, y, z;
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

M3 identity3() {
  M3 r;
  for (int i = 0; i < 3; ++i) r.m[i][i] = 1.0;
  return r;
}
M3 mul(const M3& a, const M3& b) {
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r.m[i][j] += a.m[i][k] * b.m[k][j];
  return r;
}
V3 mul(const M3& a, const V3& v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
          a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}
// Right-handed rotations about the coordinate axes, written out by hand.
M3 rotX(double a) {
  const double c = std::cos(a), s = std::sin(a);
  M3 r;
  r.m = {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
  return r;
}
M3 rotY(double a) {
  const double c = std::cos(a), s = std::sin(a);
  M3 r;
  r.m = {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
  return r;
}
M3 rotZ(double a) {
  const double c = std::cos(a), s = std::sin(a);
  M3 r;
  r.m = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
  return r;
}
M3 rotAxisLetter(char axis, const glm::dvec3& angles) {
  switch (axis) {
    case 'X': return rotX(angles.x);
    case 'Y': return rotY(angles.y);
    default: return rotZ(angles.z);
  }
}
// Rodrigues' formula: rotation by `a` about the unit axis `u`.
M3 rotAbout(const V3& u, double a) {
  const double c = std::cos(a), s = std::sin(a), t = 1.0 - c;
  M3 r;
  r.m = {{{t * u.x * u.x + c, t * u.x * u.y - s * u.z, t * u.x * u.z + s * u.y},
          {t * u.x * u.y + s * u.z, t * u.y * u.y + c, t * u.y * u.z - s * u.x},
          {t * u.x * u.z - s * u.y, t * u.y * u.z + s * u.x, t * u.z * u.z + c}}};
  return r;
}
V3 column(const M3& a, int c) { return {a.m[0][c], a.m[1][c], a.m[2][c]}; }
int axisIndex(char c) { return c - 'X'; }

// Rotates v by q with the quaternion sandwich q v q* (via glm's quat * vec3).
V3 applyQuat(const glm::quat& q, const V3& v) {
  const glm::vec3 r = q * glm::vec3(static_cast<float>(v.x), static_cast<float>(v.y),
                                    static_cast<float>(v.z));
  return {r.x, r.y, r.z};
}

// Distance between two rotations given as quaternions, insensitive to sign; about half the
// angle between them (in radians) for small differences.
double rotationDistance(const glm::quat& a, const glm::quat& b) {
  const glm::dquat da(a.w, a.x, a.y, a.z), db(b.w, b.x, b.y, b.z);
  return std::min(glm::length(da - db), glm::length(da + db));
}

// Every matrix entry of q matches `expected` (applying q to the three basis vectors).
void expectQuatMatchesMatrix(const glm::quat& q, const M3& expected, double tol,
                             const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    V3 e{0, 0, 0};
    (c == 0 ? e.x : (c == 1 ? e.y : e.z)) = 1.0;
    const V3 got = applyQuat(q, e);
    const V3 want = column(expected, c);
    EXPECT_NEAR(got.x, want.x, tol) << what << " column " << c;
    EXPECT_NEAR(got.y, want.y, tol) << what << " column " << c;
    EXPECT_NEAR(got.z, want.z, tol) << what << " column " << c;
  }
}

using test::randomRotation;
glm::vec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<float> n(0.0f, 1.0f);
  glm::vec3 v;
  do {
    v = glm::vec3(n(rng), n(rng), n(rng));
  } while (glm::dot(v, v) < 1e-4f);
  return glm::normalize(v);
}

// ---------------------------------------------------------------------------------------
// Euler orders: names and reverse.

TEST(EulerOrder, ToStringAndFromStringRoundTrip) {
  const char* names[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};
  for (int i = 0; i < 6; ++i) {
    EXPECT_STREQ(toString(kAllOrders[i]), names[i]);
    const auto parsed = eulerOrderFromString(names[i]);
    ASSERT_TRUE(parsed.has_value()) << names[i];
    EXPECT_EQ(*parsed, kAllOrders[i]);
  }
  // Case-insensitive.
  EXPECT_TRUE(eulerOrderFromString("zxy") == EulerOrder::ZXY);
  EXPECT_TRUE(eulerOrderFromString("yXz") == EulerOrder::YXZ);
  // Not an order.
  for (const char* bad : {"", "XY", "XYZZ", "XXY", "ABC", "XYX", " XYZ", "xyz "})
    EXPECT_FALSE(eulerOrderFromString(bad).has_value()) << "'" << bad << "'";
}

TEST(EulerOrder, ReversedReversesTheLetters) {
  for (EulerOrder o : kAllOrders) {
    const std::string s = toString(o);
    const std::string r = toString(reversed(o));
    EXPECT_EQ(r, std::string(s.rbegin(), s.rend())) << s;
    EXPECT_EQ(reversed(reversed(o)), o) << s;
  }
}

// ---------------------------------------------------------------------------------------
// eulerToQuat against hand-written matrices.

TEST(EulerToQuat, QuarterTurnClosedForms) {
  const float q = static_cast<float>(kPi / 2);
  const float tol = 1e-6f;
  // 90 degrees about Z: x -> y, y -> -x.
  const glm::quat rz = eulerToQuat({0.0f, 0.0f, q}, EulerOrder::XYZ);
  EXPECT_VEC3_NEAR(rz * glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), tol);
  EXPECT_VEC3_NEAR(rz * glm::vec3(0, 1, 0), glm::vec3(-1, 0, 0), tol);
  EXPECT_VEC3_NEAR(rz * glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), tol);
  // 90 degrees about X: y -> z, z -> -y.
  const glm::quat rx = eulerToQuat({q, 0.0f, 0.0f}, EulerOrder::ZYX);
  EXPECT_VEC3_NEAR(rx * glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), tol);
  EXPECT_VEC3_NEAR(rx * glm::vec3(0, 0, 1), glm::vec3(0, -1, 0), tol);
  // 90 degrees about Y: z -> x, x -> -z.
  const glm::quat ry = eulerToQuat({0.0f, q, 0.0f}, EulerOrder::YZX);
  EXPECT_VEC3_NEAR(ry * glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), tol);
  EXPECT_VEC3_NEAR(ry * glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), tol);
  // The order matters. XYZ: Rx(90) Ry(90) x = Rx(90) (-z) = y.
  EXPECT_VEC3_NEAR(eulerToQuat({q, q, 0.0f}, EulerOrder::XYZ) * glm::vec3(1, 0, 0),
                   glm::vec3(0, 1, 0), tol);
  // YXZ: Ry(90) Rx(90) x = Ry(90) x = -z.
  EXPECT_VEC3_NEAR(eulerToQuat({q, q, 0.0f}, EulerOrder::YXZ) * glm::vec3(1, 0, 0),
                   glm::vec3(0, 0, -1), tol);
  // ZXY with all three: Rz(90) Rx(90) Ry(90) x = Rz(90) Rx(90) (-z) = Rz(90) y = -x.
  EXPECT_VEC3_NEAR(eulerToQuat({q, q, q}, EulerOrder::ZXY) * glm::vec3(1, 0, 0),
                   glm::vec3(-1, 0, 0), tol);
  // ZYX: Rz(90) Ry(90) Rx(90) x = Rz(90) Ry(90) x = Rz(90) (-z) = -z.
  EXPECT_VEC3_NEAR(eulerToQuat({q, q, q}, EulerOrder::ZYX) * glm::vec3(1, 0, 0),
                   glm::vec3(0, 0, -1), tol);
}

TEST(EulerToQuat, MatchesHandWrittenMatrixProductForAllOrders) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const int cases = test::propertyCases(2000);
  for (EulerOrder o : kAllOrders) {
    const std::string name = toString(o);
    for (int n = 0; n < cases / 6 + 1; ++n) {
      const glm::vec3 a(static_cast<float>(angle(rng)), static_cast<float>(angle(rng)),
                        static_cast<float>(angle(rng)));
      const glm::dvec3 ad(a);
      // XYZ means R = Rx * Ry * Rz: multiply the matrices in the order the name lists them.
      const M3 expected = mul(mul(rotAxisLetter(name[0], ad), rotAxisLetter(name[1], ad)),
                              rotAxisLetter(name[2], ad));
      const glm::quat q = eulerToQuat(a, o);
      EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
      expectQuatMatchesMatrix(q, expected, 2e-6, name);
      if (HasFailure()) return;
    }
  }
}

TEST(EulerToQuat, IntrinsicReadingRotatesAboutMovingAxesInNameOrder) {
  // "XYZ read intrinsically: first X, then Y, then Z" about the body's moving axes. Build
  // that by turning a frame F about its own current axes with Rodrigues' formula.
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (EulerOrder o : kAllOrders) {
    const std::string name = toString(o);
    for (int n = 0; n < 50; ++n) {
      const glm::vec3 a(static_cast<float>(angle(rng)), static_cast<float>(angle(rng)),
                        static_cast<float>(angle(rng)));
      M3 frame = identity3();  // columns: the body's axes in world coordinates
      for (char letter : name) {
        const int i = axisIndex(letter);
        frame = mul(rotAbout(column(frame, i), static_cast<double>(a[i])), frame);
      }
      expectQuatMatchesMatrix(eulerToQuat(a, o), frame, 2e-6, name + " intrinsic");
      if (HasFailure()) return;
    }
  }
}

TEST(EulerToQuat, ExtrinsicReadingIsTheReversedOrder) {
  // eulerToQuat(a, order) turns about the FIXED world axes in the letter order of
  // reversed(order): e.g. XYZ = first about world Z, then world Y, then world X.
  std::mt19937 rng(78);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const V3 worldAxis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (EulerOrder o : kAllOrders) {
    const std::string rev = toString(reversed(o));
    for (int n = 0; n < 50; ++n) {
      const glm::vec3 a(static_cast<float>(angle(rng)), static_cast<float>(angle(rng)),
                        static_cast<float>(angle(rng)));
      const V3 v{0.3, -0.7, 1.1};
      V3 w = v;
      for (char letter : rev) {
        const int i = axisIndex(letter);
        w = mul(rotAbout(worldAxis[i], static_cast<double>(a[i])), w);
      }
      const V3 got = applyQuat(eulerToQuat(a, o), v);
      EXPECT_NEAR(got.x, w.x, 5e-6) << toString(o);
      EXPECT_NEAR(got.y, w.y, 5e-6) << toString(o);
      EXPECT_NEAR(got.z, w.z, 5e-6) << toString(o);
      if (HasFailure()) return;
    }
  }
  // Spelled out once: XYZ with 90 degrees about each axis. Fixed Z first: x -> y; then
  // fixed Y: y stays y; then fixed X: y -> z. So x ends on z.
  const float q = static_cast<float>(kPi / 2);
  EXPECT_VEC3_NEAR(eulerToQuat({q, q, q}, EulerOrder::XYZ) * glm::vec3(1, 0, 0),
                   glm::vec3(0, 0, 1), 1e-6f);
}

// ---------------------------------------------------------------------------------------
// quatToEuler.

TEST(QuatToEuler, RoundTripsRandomRotationsForAllOrders) {
  std::mt19937 rng(99);
  const int cases = test::propertyCases(2000);
  const float halfPi = static_cast<float>(kPi / 2);
  for (EulerOrder o : kAllOrders) {
    const std::string name = toString(o);
    const int j = axisIndex(name[1]);
    for (int n = 0; n < cases; ++n) {
      glm::quat q = randomRotation(rng);
      if (n % 2) q = -q;  // both signs describe the same rotation
      const glm::vec3 e = quatToEuler(q, o);
      ASSERT_TRUE(isFinite(e)) << name;
      EXPECT_LE(std::abs(e[j]), halfPi + 1e-6f) << name << " middle angle out of range";
      for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(e[k]), static_cast<float>(kPi) + 1e-6f);
      const glm::quat back = eulerToQuat(e, o);
      EXPECT_LT(rotationDistance(back, q), 2e-5) << name << " q=" << q.w << "," << q.x << ","
                                                 << q.y << "," << q.z;
      if (HasFailure()) return;
    }
  }
}

TEST(QuatToEuler, RecoversTheAnglesAwayFromGimbalLock) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> outer(-3.1f, 3.1f);
  std::uniform_real_distribution<float> middle(-1.4f, 1.4f);  // < 80 degrees
  for (EulerOrder o : kAllOrders) {
    const std::string name = toString(o);
    for (int n = 0; n < 300; ++n) {
      glm::vec3 a;
      for (int k = 0; k < 3; ++k) a[k] = k == axisIndex(name[1]) ? middle(rng) : outer(rng);
      const glm::vec3 e = quatToEuler(eulerToQuat(a, o), o);
      EXPECT_VEC3_NEAR(e, a, 2e-4f);
      if (HasFailure()) return;
    }
  }
}

TEST(QuatToEuler, GimbalLockForEveryOrder) {
  // Middle angle exactly +-90 degrees: only a combination of the outer angles is defined.
  // The result must still describe the same rotation, with the third angle set to 0.
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> outer(-3.1f, 3.1f);
  const float halfPi = static_cast<float>(kPi / 2);
  for (EulerOrder o : kAllOrders) {
    const std::string name = toString(o);
    const int i = axisIndex(name[0]), j = axisIndex(name[1]), k = axisIndex(name[2]);
    for (float sign : {1.0f, -1.0f}) {
      for (int n = 0; n < 100; ++n) {
        glm::vec3 a;
        a[i] = n == 0 ? 0.0f : outer(rng);
        a[j] = sign * halfPi;
        a[k] = n == 0 ? 0.0f : outer(rng);
        const glm::quat q = eulerToQuat(a, o);
        const glm::vec3 e = quatToEuler(q, o);
        ASSERT_TRUE(isFinite(e)) << name;
        EXPECT_NEAR(e[j], sign * halfPi, 1e-5f) << name;
        EXPECT_NEAR(e[k], 0.0f, 1e-6f) << name << " third angle at gimbal lock";
        EXPECT_LT(rotationDistance(eulerToQuat(e, o), q), 2e-5)
            << name << " angles " << a.x << "," << a.y << "," << a.z << " -> " << e.x << ","
            << e.y << "," << e.z;
        // Also through the hand-written matrices.
        const glm::dvec3 ed(e);
        const M3 m = mul(mul(rotAxisLetter(name[0], ed), rotAxisLetter(name[1], ed)),
                         rotAxisLetter(name[2], ed));
        expectQuatMatchesMatrix(q, m, 5e-5, name + " gimbal");
        if (HasFailure()) return;
      }
    }
  }
}

TEST(QuatToEuler, NearGimbalLockStillRoundTrips) {
  // Middle angles just short of +-90 degrees, where asin(sin b) loses half its digits and the
  // split between the outer angles is ill-conditioned: the rotation must still come back.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> outer(-3.1f, 3.1f);
  for (EulerOrder o : kAllOrders) {
    const std::string name = toString(o);
    const int j = axisIndex(name[1]);
    for (double off : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
      for (float sign : {1.0f, -1.0f}) {
        for (int n = 0; n < 20; ++n) {
          glm::vec3 a(outer(rng), outer(rng), outer(rng));
          a[j] = sign * static_cast<float>(kPi / 2 - off);
          const glm::quat q = eulerToQuat(a, o);
          const glm::vec3 e = quatToEuler(q, o);
          EXPECT_LT(rotationDistance(eulerToQuat(e, o), q), 2e-5) << name << " off " << off;
          EXPECT_NEAR(e[j], a[j], 1e-4f) << name << " off " << off;
          if (HasFailure()) return;
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------
// Axis-angle.

TEST(AxisAngle, RoundTripWithAngleInZeroToPi) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> ang(0.01f, 3.13f);
  std::uniform_real_distribution<float> scale(0.1f, 10.0f);
  for (int n = 0; n < test::propertyCases(2000); ++n) {
    const glm::vec3 axis = randomUnit(rng);
    const float a = ang(rng);
    const glm::quat q = axisAngle(axis * scale(rng), a);  // axis need not be unit
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
    // Against Rodrigues' formula.
    const M3 m = rotAbout({axis.x, axis.y, axis.z}, a);
    expectQuatMatchesMatrix(q, m, 2e-6, "axisAngle");
    glm::vec3 axisOut;
    float angleOut = -1.0f;
    toAxisAngle(q, axisOut, angleOut);
    EXPECT_NEAR(angleOut, a, 1e-5f);
    EXPECT_VEC3_NEAR(axisOut, axis, 1e-4f);
    // -q: same rotation, same answer.
    toAxisAngle(-q, axisOut, angleOut);
    EXPECT_NEAR(angleOut, a, 1e-5f);
    EXPECT_VEC3_NEAR(axisOut, axis, 1e-4f);
    // An angle beyond pi comes back as 2 pi - angle about the opposite axis.
    const float big = 2.0f * static_cast<float>(kPi) - a;
    toAxisAngle(axisAngle(axis, big), axisOut, angleOut);
    EXPECT_NEAR(angleOut, a, 1e-5f);
    EXPECT_VEC3_NEAR(axisOut, -axis, 1e-4f);
    if (HasFailure()) return;
  }
}

TEST(AxisAngle, IdentityAndDegenerateAxes) {
  glm::vec3 axis(9.0f);
  float angle = 9.0f;
  toAxisAngle(glm::quat(1, 0, 0, 0), axis, angle);
  EXPECT_EQ(angle, 0.0f);
  EXPECT_EQ(axis, glm::vec3(1, 0, 0));
  toAxisAngle(glm::quat(-1, 0, 0, 0), axis, angle);
  EXPECT_EQ(angle, 0.0f);
  EXPECT_NEAR(glm::length(axis), 1.0f, 1e-6f);
  // Half a turn exactly.
  toAxisAngle(glm::quat(0, 0, 0, 1), axis, angle);
  EXPECT_NEAR(angle, static_cast<float>(kPi), 1e-6f);
  EXPECT_VEC3_NEAR(axis, glm::vec3(0, 0, 1), 1e-6f);
  // A zero axis gives identity; a NaN axis too.
  EXPECT_EQ(axisAngle(glm::vec3(0.0f), 1.0f), glm::quat(1, 0, 0, 0));
  EXPECT_EQ(axisAngle(glm::vec3(NAN, 0.0f, 0.0f), 1.0f), glm::quat(1, 0, 0, 0));
}

// ---------------------------------------------------------------------------------------
// Swing-twist.

void expectSwingTwistInvariants(const glm::quat& qIn, const glm::vec3& axis) {
  const glm::quat q = glm::normalize(qIn);
  const SwingTwist st = swingTwist(q, axis);
  EXPECT_NEAR(glm::length(st.swing), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(st.twist), 1.0f, 1e-5f);
  // Recomposes q exactly (not just up to sign).
  const glm::quat r = st.swing * st.twist;
  EXPECT_NEAR(r.w, q.w, 1e-6f);
  EXPECT_NEAR(r.x, q.x, 1e-6f);
  EXPECT_NEAR(r.y, q.y, 1e-6f);
  EXPECT_NEAR(r.z, q.z, 1e-6f);
  // Twist vector part parallel to the axis; swing vector part perpendicular to it.
  const glm::vec3 tv(st.twist.x, st.twist.y, st.twist.z);
  const glm::vec3 sv(st.swing.x, st.swing.y, st.swing.z);
  EXPECT_LT(glm::length(glm::cross(tv, axis)), 2e-6f);
  EXPECT_NEAR(glm::dot(sv, axis), 0.0f, 2e-6f);
  // Twist leaves the axis where it is; swing moves the axis exactly as q does.
  EXPECT_VEC3_NEAR(st.twist * axis, axis, 5e-6f);
  EXPECT_VEC3_NEAR(st.swing * axis, q * axis, 5e-6f);
}

TEST(SwingTwist, RandomRotationsAndAxes) {
  std::mt19937 rng(21);
  for (int n = 0; n < test::propertyCases(2000); ++n) {
    const glm::quat q = randomRotation(rng);
    const glm::vec3 axis = randomUnit(rng);
    expectSwingTwistInvariants(q, axis);
    if (HasFailure()) return;
  }
  // Coordinate axes too.
  for (const glm::vec3 axis : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, -1)}) {
    for (int n = 0; n < 50; ++n) expectSwingTwistInvariants(randomRotation(rng), axis);
  }
}

TEST(SwingTwist, PureTwistAndPureSwing) {
  const glm::vec3 y(0, 1, 0);
  // 60 degrees about Y, twist axis Y: all twist.
  const glm::quat twistOnly(std::cos(deg(30)), 0.0f, std::sin(deg(30)), 0.0f);
  SwingTwist st = swingTwist(twistOnly, y);
  EXPECT_LT(rotationDistance(st.twist, twistOnly), 1e-6);
  EXPECT_LT(rotationDistance(st.swing, glm::quat(1, 0, 0, 0)), 1e-6);
  // 60 degrees about X, twist axis Y: all swing.
  const glm::quat swingOnly(std::cos(deg(30)), std::sin(deg(30)), 0.0f, 0.0f);
  st = swingTwist(swingOnly, y);
  EXPECT_LT(rotationDistance(st.swing, swingOnly), 1e-6);
  EXPECT_LT(rotationDistance(st.twist, glm::quat(1, 0, 0, 0)), 1e-6);
  // Rx(90) then... q = swing(90 about X) * twist(90 about Y): components recovered.
  const glm::quat sw(std::cos(deg(45)), std::sin(deg(45)), 0.0f, 0.0f);
  const glm::quat tw(std::cos(deg(45)), 0.0f, std::sin(deg(45)), 0.0f);
  st = swingTwist(sw * tw, y);
  EXPECT_LT(rotationDistance(st.swing, sw), 1e-6);
  EXPECT_LT(rotationDistance(st.twist, tw), 1e-6);
}

TEST(SwingTwist, HalfTurnSwingPerpendicularToTheTwistAxis) {
  // q = 180 degrees about an axis perpendicular to the twist axis: the vector part of q is
  // perpendicular to the axis and w = 0, so the twist is undefined; it must come out as
  // identity and the swing as q, without NaN.
  const glm::quat halfTurnX(0.0f, 1.0f, 0.0f, 0.0f);
  for (const glm::vec3 axis : {glm::vec3(0, 1, 0), glm::vec3(0, 0, 1),
                               glm::normalize(glm::vec3(0, 1, -1))}) {
    const SwingTwist st = swingTwist(halfTurnX, axis);
    ASSERT_TRUE(isFinite(st.swing) && isFinite(st.twist));
    EXPECT_LT(rotationDistance(st.twist, glm::quat(1, 0, 0, 0)), 1e-6);
    EXPECT_LT(rotationDistance(st.swing, halfTurnX), 1e-6);
    expectSwingTwistInvariants(halfTurnX, axis);
  }
  // The same with a half turn built from an angle (w is only approximately 0).
  const glm::vec3 perp = glm::normalize(glm::vec3(1, 0, 1));
  const glm::quat q = axisAngle(perp, static_cast<float>(kPi));
  const SwingTwist st = swingTwist(q, glm::vec3(0, 1, 0));
  ASSERT_TRUE(isFinite(st.swing) && isFinite(st.twist));
  EXPECT_LT(rotationDistance(st.swing, q), 1e-6);
  expectSwingTwistInvariants(q, glm::vec3(0, 1, 0));
}

// ---------------------------------------------------------------------------------------
// fromToRotation.

TEST(FromToRotation, MapsFromOntoToForRandomNonUnitVectors) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<float> len(0.01f, 100.0f);
  for (int n = 0; n < test::propertyCases(2000); ++n) {
    const glm::vec3 a = randomUnit(rng), b = randomUnit(rng);
    const glm::quat q = fromToRotation(a * len(rng), b * len(rng));
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
    EXPECT_VEC3_NEAR(q * a, b, 1e-4f);
    // Shortest: the angle turned is the angle between the vectors, about their normal.
    glm::vec3 axis;
    float angle;
    toAxisAngle(q, axis, angle);
    const double between = std::acos(std::clamp(static_cast<double>(glm::dot(a, b)), -1.0, 1.0));
    EXPECT_NEAR(angle, between, 1e-3);
    if (between > 0.01 && between < kPi - 0.01) {
      EXPECT_NEAR(glm::dot(axis, a), 0.0f, 1e-3f);
      EXPECT_NEAR(glm::dot(axis, b), 0.0f, 1e-3f);
    }
    if (HasFailure()) return;
  }
}

TEST(FromToRotation, ParallelGivesIdentity) {
  for (const glm::vec3 v : {glm::vec3(1, 2, 3), glm::vec3(1, 0, 0), glm::vec3(0, -4, 0)}) {
    const glm::quat q = fromToRotation(v, 2.5f * v);
    EXPECT_LT(rotationDistance(q, glm::quat(1, 0, 0, 0)), 1e-6) << v.x << "," << v.y << "," << v.z;
  }
}

TEST(FromToRotation, AntiparallelTurnsHalfWayAboutAPerpendicularAxis) {
  for (const glm::vec3 v : {glm::vec3(1, 2, 3), glm::vec3(1, 0, 0), glm::vec3(-3, 0, 0),
                            glm::vec3(0, 0.5f, 0), glm::vec3(0, 0, 2)}) {
    const glm::quat q = fromToRotation(v, -0.3f * v);
    ASSERT_TRUE(isFinite(q));
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
    const glm::vec3 u = glm::normalize(v);
    EXPECT_VEC3_NEAR(q * u, -u, 1e-5f);
    glm::vec3 axis;
    float angle;
    toAxisAngle(q, axis, angle);
    EXPECT_NEAR(angle, static_cast<float>(kPi), 1e-3f);
    EXPECT_NEAR(glm::dot(axis, u), 0.0f, 1e-5f);
  }
}

TEST(FromToRotation, QuarterTurnClosedForm) {
  // x onto y: 90 degrees about +Z, q = (cos 45, 0, 0, sin 45).
  const glm::quat q = fromToRotation({2, 0, 0}, {0, 5, 0});
  const float h = static_cast<float>(std::sqrt(0.5));
  EXPECT_NEAR(q.w, h, 1e-6f);
  EXPECT_NEAR(q.x, 0.0f, 1e-6f);
  EXPECT_NEAR(q.y, 0.0f, 1e-6f);
  EXPECT_NEAR(q.z, h, 1e-6f);
  // Zero input: identity, no NaN.
  EXPECT_EQ(fromToRotation({0, 0, 0}, {1, 0, 0}), glm::quat(1, 0, 0, 0));
  EXPECT_EQ(fromToRotation({1, 0, 0}, {0, 0, 0}), glm::quat(1, 0, 0, 0));
}

// ---------------------------------------------------------------------------------------
// slerpShortest, sameHemisphere, safeNormalize.

TEST(SlerpShortest, TakesTheShortArcWhenGivenTheNegatedEndpoint) {
  // b = 170 degrees about Y, passed as -b. Short arc from identity: 85 degrees about +Y at
  // the midpoint (the long way would give 95 degrees about -Y).
  const glm::quat a(1, 0, 0, 0);
  const glm::quat b(std::cos(deg(85)), 0.0f, std::sin(deg(85)), 0.0f);
  const glm::quat mid = slerpShortest(a, -b, 0.5f);
  glm::vec3 axis;
  float angle;
  toAxisAngle(mid, axis, angle);
  EXPECT_NEAR(angle, deg(85), 1e-5);
  EXPECT_VEC3_NEAR(axis, glm::vec3(0, 1, 0), 1e-5f);
  // Directly against the closed form.
  const glm::quat expected(std::cos(deg(42.5)), 0.0f, std::sin(deg(42.5)), 0.0f);
  EXPECT_LT(rotationDistance(mid, expected), 1e-6);
  // Constant angular speed: at t = 0.2 the angle is 34 degrees.
  toAxisAngle(slerpShortest(a, -b, 0.2f), axis, angle);
  EXPECT_NEAR(angle, deg(34), 1e-5);
}

TEST(SlerpShortest, EndpointsAndUnitLength) {
  std::mt19937 rng(41);
  for (int n = 0; n < test::propertyCases(2000); ++n) {
    const glm::quat a = randomRotation(rng), b = randomRotation(rng);
    EXPECT_LT(rotationDistance(slerpShortest(a, b, 0.0f), a), 1e-6);
    EXPECT_LT(rotationDistance(slerpShortest(a, b, 1.0f), b), 1e-6);
    for (float t : {0.1f, 0.5f, 0.77f}) {
      const glm::quat s = slerpShortest(a, b, t);
      EXPECT_NEAR(glm::length(s), 1.0f, 1e-5f);
      // Never more than the short way: angle(a, s) = t * angle(a, b), angle(a,b) <= pi.
      const double full = 2.0 * std::acos(std::min(1.0, std::abs(static_cast<double>(glm::dot(a, b)))));
      const double part = 2.0 * std::acos(std::min(1.0, std::abs(static_cast<double>(glm::dot(a, s)))));
      EXPECT_NEAR(part, t * full, 2e-3);
    }
    if (HasFailure()) return;
  }
  // Nearly equal rotations (the normalised-lerp fallback) stay unit.
  const glm::quat a = axisAngle({0, 0, 1}, 0.3f), b = axisAngle({0, 0, 1}, 0.3001f);
  EXPECT_NEAR(glm::length(slerpShortest(a, b, 0.5f)), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(slerpShortest(a, -b, 0.5f)), 1.0f, 1e-6f);
}

TEST(SameHemisphere, FlipsOnlyWhenTheDotIsNegative) {
  const glm::quat ref(1, 0, 0, 0);
  const glm::quat q(-0.6f, 0.8f, 0.0f, 0.0f);
  EXPECT_EQ(sameHemisphere(q, ref), -q);
  EXPECT_EQ(sameHemisphere(-q, ref), -q);
}

TEST(SafeNormalize, ZeroNaNAndInfinityGiveIdentity) {
  const glm::quat id(1, 0, 0, 0);
  EXPECT_EQ(safeNormalize(glm::quat(0, 0, 0, 0)), id);
  EXPECT_EQ(safeNormalize(glm::quat(NAN, 0, 0, 0)), id);
  EXPECT_EQ(safeNormalize(glm::quat(1, NAN, 0, 0)), id);
  EXPECT_EQ(safeNormalize(glm::quat(INFINITY, 0, 0, 0)), id);
  const glm::quat n = safeNormalize(glm::quat(0, 0, 3, 4));
  EXPECT_NEAR(n.w, 0.0f, 1e-7f);
  EXPECT_NEAR(n.y, 0.6f, 1e-6f);
  EXPECT_NEAR(n.z, 0.8f, 1e-6f);
  // Sign is kept.
  const glm::quat m = safeNormalize(glm::quat(-2, 0, 0, 0));
  EXPECT_EQ(m, glm::quat(-1, 0, 0, 0));
}

}  // namespace
}  // namespace kinema

namespace kinema {
namespace KINEMA_UNITY_ID {

// Found by fuzz_clip_sampling: a key quaternion with denormal-sized components normalised
// to length 0.8 because its squared length underflowed.
TEST(SafeNormalizeRegression, TinyAndHugeQuaternionsBecomeUnit) {
  const glm::quat tiny(1.2830024e-22f, 0.0f, 0.0f, 9.183409e-41f);  // (w, x, y, z)
  const glm::quat n = safeNormalize(tiny);
  EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  EXPECT_NEAR(n.w, 1.0f, 1e-6f);
  const glm::quat denormal(0.0f, 1e-45f, 0.0f, 1e-45f);  // x and z equal, both denormal
  const glm::quat d = safeNormalize(denormal);
  EXPECT_NEAR(d.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(d.z, std::sqrt(0.5f), 1e-6f);
  const glm::quat huge(3e38f, 3e38f, 0.0f, 0.0f);  // squared length overflows float
  const glm::quat h = safeNormalize(huge);
  EXPECT_NEAR(h.w, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(h.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_EQ(safeNormalize(glm::quat(NAN, 1.0f, 0.0f, 0.0f)), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
}

}  // namespace
}  // namespace kinema
