#include "io/image.h"

#include "test_support.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

TEST(Image, PngRoundTripIsExact) {
  Image img(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 50), p[1] = static_cast<std::uint8_t>(y * 100), p[2] = 7, p[3] = 255;
    }
  const std::string dir = makeTempDir(), path = dir + "/a.png";
  ASSERT_EQ(savePng(path, img), "");
  Result<Image> back = loadPng(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->width, 5);
  EXPECT_EQ(back->height, 3);
  EXPECT_EQ(back->rgba, img.rgba);
  runCommand("rm -rf '" + dir + "'");
}

TEST(Image, FlipVerticallySwapsRows) {
  Image img(1, 3);
  for (int y = 0; y < 3; ++y) img.pixel(0, y)[0] = static_cast<std::uint8_t>(y);
  img.flipVertically();
  EXPECT_EQ(img.pixel(0, 0)[0], 2);
  EXPECT_EQ(img.pixel(0, 1)[0], 1);
  EXPECT_EQ(img.pixel(0, 2)[0], 0);
}

TEST(Image, BadInputFailsWithThePath) {
  EXPECT_NE(savePng("/nonexistent-dir/x.png", Image(2, 2)).find("/nonexistent-dir/x.png"), std::string::npos);
  EXPECT_NE(savePng("x.png", Image()).find("empty"), std::string::npos);
  Result<Image> r = loadPng("/nonexistent-dir/y.png");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error().find("/nonexistent-dir/y.png"), std::string::npos);
}

}  // namespace
}  // namespace kinema::test
