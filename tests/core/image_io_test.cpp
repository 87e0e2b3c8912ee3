// Image I/O through OpenImageIO: exact PNG round trips, straight alpha, JPEG, float EXR.
#include "core/image.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/files.h"
#include "temp_dir.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

using testing::FreshFolder;

Image8 ChannelPattern(int width, int height, int channels) {
  Image8 image(width, height, channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c) image.at(x, y, c) = uint8_t((x * 37 + y * 11 + c * 91) & 0xff);
  return image;
}

TEST(ImageIo, PngRoundTripsExactlyForOneThreeAndFourChannels) {
  const fs::path folder = FreshFolder("png");
  for (int channels : {1, 3, 4}) {
    const Image8 image = ChannelPattern(23, 17, channels);
    const fs::path path = folder / Str("p", channels, ".png");
    WriteImage(path, image);
    EXPECT_EQ(ReadImage8(path), image) << channels << " channels";
    EXPECT_EQ(ReadImageSize(path), std::make_pair(23, 17));
  }
  // Deterministic bytes: writing the same image twice gives the same file.
  WriteImage(folder / "again.png", ChannelPattern(23, 17, 4));
  EXPECT_EQ(ReadFile(folder / "again.png"), ReadFile(folder / "p4.png"));
}

TEST(ImageIo, StraightAlphaIsPreservedExactly) {
  const fs::path folder = FreshFolder("alpha");
  Image8 image(4, 1, 4);
  const uint8_t pixels[] = {200, 100, 50, 0,  // colour under zero alpha must survive
                            200, 100, 50, 1, 200, 100, 50, 128, 255, 255, 255, 255};
  image.pixels.assign(std::begin(pixels), std::end(pixels));
  WriteImage(folder / "a.png", image);
  EXPECT_EQ(ReadImage8(folder / "a.png"), image);
  // As a matte, one channel takes the alpha.
  const Image8 matte = ReadImage8(folder / "a.png", 1);
  ASSERT_EQ(matte.channels, 1);
  EXPECT_EQ(matte.pixels, (std::vector<uint8_t>{0, 1, 128, 255}));
  // Grey -> RGB replicates; RGB -> RGBA adds opaque alpha.
  WriteImage(folder / "g.png", ChannelPattern(3, 2, 1));
  const Image8 rgb = ReadImage8(folder / "g.png", 3);
  EXPECT_EQ(rgb.at(2, 1, 0), rgb.at(2, 1, 2));
  const Image8 rgba = ReadImage8(folder / "g.png", 4);
  EXPECT_EQ(rgba.at(1, 1, 3), 255);
}

TEST(ImageIo, JpegIsReadable) {
  const fs::path folder = FreshFolder("jpeg");
  Image8 image(32, 32, 3);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      image.at(x, y, 0) = uint8_t(x * 8);
      image.at(x, y, 1) = uint8_t(y * 8);
      image.at(x, y, 2) = 128;
    }
  WriteImage(folder / "a.jpg", image);
  const Image8 read = ReadImage8(folder / "a.jpg");
  ASSERT_EQ(read.width, 32);
  ASSERT_EQ(read.channels, 3);
  double error = 0;
  for (size_t i = 0; i < read.pixels.size(); ++i) error += std::abs(int(read.pixels[i]) - int(image.pixels[i]));
  // Lossy, but a smooth ramp stays close: measured mean absolute error about 1 level.
  EXPECT_LT(error / double(read.pixels.size()), 4.0);
}

TEST(ImageIo, ExrKeepsFloatsExactly) {
  const fs::path folder = FreshFolder("exr");
  ImageF image(5, 3, 4);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i) * 0.123456789f - 1.5f;
  image.pixels[3] = 1e-7f;
  WriteImage(folder / "a.exr", image);
  auto input = OIIO::ImageInput::open((folder / "a.exr").string());
  ASSERT_TRUE(input);
  ASSERT_EQ(input->spec().nchannels, 4);
  ImageF read(input->spec().width, input->spec().height, 4);
  ASSERT_TRUE(input->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, read.pixels.data()));
  EXPECT_EQ(read.pixels, image.pixels);
}

TEST(ImageIo, TruncatedJpegIsRefusedNotReadAsGrey) {
  const fs::path folder = FreshFolder("truncated");
  WriteImage(folder / "whole.jpg", ChannelPattern(64, 48, 3));
  const std::string bytes = ReadFile(folder / "whole.jpg");
  WriteFileAtomic(folder / "half.jpg", bytes.substr(0, bytes.size() / 2));
  EXPECT_NO_THROW(ReadImage8(folder / "whole.jpg"));
  try {
    ReadImage8(folder / "half.jpg");
    FAIL() << "a truncated JPEG was decoded";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("half.jpg"), std::string::npos) << message;
    EXPECT_NE(message.find("damaged image"), std::string::npos) << message;
  }
}

TEST(ImageIo, FloatPhotosAreEncodedAsSrgb) {
  const fs::path folder = FreshFolder("exr_photo");
  ImageF linear(4, 1, 3);
  const float values[4] = {0.0f, 0.2158605f, 1.0f, 4.0f};  // 0.2158605 is sRGB 128/255 in linear light
  for (int x = 0; x < 4; ++x)
    for (int c = 0; c < 3; ++c) linear.at(x, 0, c) = values[x];
  WriteImage(folder / "photo.exr", linear);
  const Image8 read = ReadImage8(folder / "photo.exr", 3);
  ASSERT_EQ(read.width, 4);
  EXPECT_EQ(read.at(0, 0, 0), 0);
  EXPECT_EQ(read.at(1, 0, 1), 128);
  EXPECT_EQ(read.at(2, 0, 2), 255);
  EXPECT_EQ(read.at(3, 0, 0), 255);  // brighter than white is clamped
}

TEST(ImageIo, ErrorsNameTheFile) {
  const fs::path folder = FreshFolder("errors");
  WriteFileAtomic(folder / "broken.png", "not a png at all");
  for (const fs::path& path : {folder / "missing.png", folder / "broken.png"}) {
    try {
      ReadImage8(path);
      FAIL() << "expected an Error for " << path;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(path.filename().string()), std::string::npos) << error.what();
    }
  }
  EXPECT_THROW(WriteImage(folder / "empty.png", Image8{}), Error);
}

}  // namespace
}  // namespace voltree
