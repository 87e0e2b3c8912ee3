#include "core/image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <unistd.h>

#include <cstdio>

#include "core/error.h"
#include "core/interrupt_cleanup.h"
#include "core/image_size_guard.h"
#include "core/srgb.h"

namespace voltree {
namespace fs = std::filesystem;
using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

namespace {

template <typename T>
Image<T> ConvertChannels(const Image<T>& in, int channels, T opaque) {
  if (channels <= 0 || channels == in.channels) return in;
  Image<T> out(in.width, in.height, channels);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      for (int c = 0; c < channels; ++c) {
        T value;
        if (channels == 1)  // a matte: alpha if there is one, else the first channel
          value = in.channels == 4 || in.channels == 2 ? in.at(x, y, in.channels - 1) : in.at(x, y, 0);
        else if (c < 3)
          value = in.channels >= 3 ? in.at(x, y, c) : in.at(x, y, 0);
        else
          value = in.channels == 4 ? in.at(x, y, 3) : in.channels == 2 ? in.at(x, y, 1) : opaque;
        out.at(x, y, c) = value;
      }
    }
  return out;
}

template <typename T>
void WriteWithOiio(const fs::path& path, const Image<T>& image, TypeDesc type) {
  if (image.empty()) Fail(path.string(), ": refusing to write an empty image");
  const auto writing = HoldOffInterruptCleanup();
  if (!path.parent_path().empty()) fs::create_directories(path.parent_path());
  // Keep the extension on the temporary name: OpenImageIO picks the format from it.
  const fs::path temporary =
      path.parent_path() / Str(".", path.stem().string(), ".tmp-", ::getpid(), path.extension().string());
  auto output = ImageOutput::create(path.string());
  if (!output) Fail(path.string(), ": no image writer for this extension (", OIIO::geterror(), ")");
  ImageSpec spec(image.width, image.height, image.channels, type);
  if (image.channels == 4) spec.alpha_channel = 3;
  spec.attribute("oiio:UnassociatedAlpha", 1);  // our pixels are straight; do not un-premultiply
  if (!output->open(temporary.string(), spec) || !output->write_image(type, image.pixels.data()) || !output->close()) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    Fail(path.string(), ": cannot write image: ", output->geterror());
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) Fail(path.string(), ": cannot move the finished image into place");
}

// Turns stored pixels upright as the EXIF "Orientation" (1..8) says cameras meant them to be shown.
Image8 Reorient(const Image8& in, int orientation) {
  if (orientation < 2 || orientation > 8) return in;
  const bool swap = orientation >= 5;
  const int w = in.width, h = in.height;
  Image8 out(swap ? h : w, swap ? w : h, in.channels);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      int sx = x, sy = y;
      switch (orientation) {
        case 2:
          sx = w - 1 - x;
          break;
        case 3:
          sx = w - 1 - x;
          sy = h - 1 - y;
          break;
        case 4:
          sy = h - 1 - y;
          break;
        case 5:
          sx = y;
          sy = x;
          break;
        case 6:
          sx = y;
          sy = h - 1 - x;
          break;
        case 7:
          sx = w - 1 - y;
          sy = h - 1 - x;
          break;
        case 8:
          sx = w - 1 - y;
          sy = x;
          break;
      }
      for (int c = 0; c < in.channels; ++c) out.at(x, y, c) = in.at(sx, sy, c);
    }
  return out;
}

// Linear floating-point photos (EXR, HDR) become 8-bit sRGB: colour through the sRGB curve, alpha
// (linear by definition) scaled.
Image8 EncodeLinearAsSrgb(const ImageF& linear) {
  Image8 out(linear.width, linear.height, linear.channels);
  const bool has_alpha = linear.channels == 2 || linear.channels == 4;
  for (size_t i = 0; i < linear.pixels.size(); ++i) {
    const bool alpha = has_alpha && int(i % linear.channels) == linear.channels - 1;
    float value = std::clamp(std::isfinite(linear.pixels[i]) ? linear.pixels[i] : 0.0f, 0.0f, 1.0f);
    if (!alpha) value = LinearToSrgb(value);
    out.pixels[i] = uint8_t(std::lround(value * 255.0f));
  }
  return out;
}

bool IsFloatingPoint(const ImageSpec& spec) {
  return spec.format.basetype == TypeDesc::FLOAT || spec.format.basetype == TypeDesc::HALF ||
         spec.format.basetype == TypeDesc::DOUBLE;
}

// Decoders report damage (a truncated JPEG: "Premature end of JPEG file") as a message while
// returning success and grey pixels; a photo with such a message is refused, not used.
void FailOnDecoderMessage(const fs::path& path, ImageInput& input) {
  const std::string message = input.geterror();
  if (!message.empty()) Fail(path.string(), ": damaged image (", message, "); expected a complete file");
}

template <typename T>
Image<T> DecodePixels(const fs::path& path, ImageInput& input, TypeDesc type) {
  const ImageSpec& spec = input.spec();
  try {
    Image<T> image(spec.width, spec.height, spec.nchannels);
    if (!input.read_image(0, 0, 0, spec.nchannels, type, image.pixels.data()))
      Fail(path.string(), ": cannot decode image: ", input.geterror());
    FailOnDecoderMessage(path, input);
    return image;
  } catch (const std::bad_alloc&) {
    Fail(path.string(), ": not enough memory to decode its ", spec.width, "x", spec.height, " pixels");
  }
}

}  // namespace

Image8 ReadImage8(const fs::path& path, int channels) {
  // Images are stored straight (un-associated alpha) as PNG does; without this hint OpenImageIO
  // would premultiply on read.
  ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = ImageInput::open(path.string(), &config);
  if (!input) Fail(path.string(), ": cannot read image: ", OIIO::geterror());
  const ImageSpec& spec = input->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.nchannels > 4)
    Fail(path.string(), ": unsupported image (", spec.width, "x", spec.height, ", ", spec.nchannels, " channels)");
  const bool floating = IsFloatingPoint(spec);
  CheckImageSizeBeforeDecoding(path, spec.width, spec.height, std::max(spec.nchannels, channels),
                               floating ? int(sizeof(float)) : 1);
  Image8 image = floating ? EncodeLinearAsSrgb(DecodePixels<float>(path, *input, TypeDesc::FLOAT))
                          : DecodePixels<uint8_t>(path, *input, TypeDesc::UINT8);
  image = Reorient(image, spec.get_int_attribute("Orientation", 1));
  return ConvertChannels<uint8_t>(image, channels, 255);
}

std::pair<int, int> ReadImageSize(const fs::path& path) {
  auto input = ImageInput::open(path.string());
  if (!input) Fail(path.string(), ": cannot read image: ", OIIO::geterror());
  const bool swapped = input->spec().get_int_attribute("Orientation", 1) >= 5;  // turned by 90 degrees
  if (swapped) return {input->spec().height, input->spec().width};
  return {input->spec().width, input->spec().height};
}

void WriteImage(const fs::path& path, const Image8& image) { WriteWithOiio(path, image, TypeDesc::UINT8); }
void WriteImage(const fs::path& path, const ImageF& image) { WriteWithOiio(path, image, TypeDesc::FLOAT); }

}  // namespace voltree
