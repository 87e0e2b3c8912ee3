#include "samples/import_texture.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/error.h"

namespace voltree {
namespace {

// OpenImageIO picks the reader from the name's extension, so map what we know to one.
std::string ExtensionFor(std::span<const uint8_t> bytes, const std::string& format_hint) {
  static const uint8_t kPng[] = {0x89, 'P', 'N', 'G'};
  if (bytes.size() >= 4 && std::equal(kPng, kPng + 4, bytes.begin())) return ".png";
  if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return ".jpg";
  if (bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M') return ".bmp";
  const size_t slash = format_hint.rfind('/');
  if (format_hint.rfind("image/", 0) == 0 && slash != std::string::npos)
    return std::string(".").append(format_hint, slash + 1);  // image/webp -> .webp
  return std::filesystem::path(format_hint).extension().string();
}

uint8_t Bilinear(const Image8& image, float x, float y) {
  x = std::clamp(x, 0.0f, float(image.width - 1));
  y = std::clamp(y, 0.0f, float(image.height - 1));
  const int x0 = int(x), y0 = int(y);
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const float fx = x - x0, fy = y - y0;
  const float top = image.at(x0, y0) * (1 - fx) + image.at(x1, y0) * fx;
  const float bottom = image.at(x0, y1) * (1 - fx) + image.at(x1, y1) * fx;
  return uint8_t(std::lround(top * (1 - fy) + bottom * fy));
}

}  // namespace

Image8 ToRgba8(const Image8& image) {
  if (image.channels == 4) return image;
  Image8 out(image.width, image.height, 4, 255);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const bool has_colour = image.channels >= 3;
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = image.at(x, y, has_colour ? c : 0);
      if (image.channels == 2) out.at(x, y, 3) = image.at(x, y, 1);
    }
  return out;
}

Image8 DecodeImageRgba8(std::span<const uint8_t> bytes, const std::string& format_hint, const std::string& what) {
  if (bytes.empty()) Fail(what, ": the image is empty");
  const std::string extension = ExtensionFor(bytes, format_hint);
  if (extension.empty()) Fail(what, ": unknown image format (expected PNG or JPEG)");
  OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
  OIIO::Filesystem::IOProxy* proxy = &reader;
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // keep straight alpha as PNG stores it
  // OpenImageIO 2.4 reads from memory through this hint; its `ioproxy` argument to open() fails
  // with "Could not open file" for PNG.
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto input = OIIO::ImageInput::open("texture" + extension, &config);
  if (!input) Fail(what, ": cannot decode image: ", OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.nchannels > 4)
    Fail(what, ": unsupported image (", spec.width, "x", spec.height, ", ", spec.nchannels, " channels)");
  Image8 image(spec.width, spec.height, spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, image.pixels.data()))
    Fail(what, ": cannot decode image: ", input->geterror());
  return ToRgba8(image);
}

Image8 ReadImageRgba8(const std::filesystem::path& path) { return ToRgba8(ReadImage8(path)); }

bool HasTransparency(const Image8& rgba) {
  for (size_t i = 3; i < rgba.pixels.size(); i += 4)
    if (rgba.pixels[i] != 255) return true;
  return false;
}

Image8 CoverageFromAlphaMap(const Image8& alpha_map) {
  const bool use_alpha = (alpha_map.channels == 4 && HasTransparency(alpha_map)) || alpha_map.channels == 2;
  const int channel = use_alpha ? alpha_map.channels - 1 : 0;
  Image8 coverage(alpha_map.width, alpha_map.height, 1);
  for (int y = 0; y < alpha_map.height; ++y)
    for (int x = 0; x < alpha_map.width; ++x) coverage.at(x, y) = alpha_map.at(x, y, channel);
  return coverage;
}

Image8 MultiplyAlpha(const Image8& colour, const Image8& coverage) {
  Image8 out = ToRgba8(colour);
  // Texel centres map to texel centres, as a GPU sampler would line them up.
  const float sx = float(coverage.width) / out.width, sy = float(coverage.height) / out.height;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const uint8_t a = Bilinear(coverage, (x + 0.5f) * sx - 0.5f, (y + 0.5f) * sy - 0.5f);
      out.at(x, y, 3) = uint8_t((out.at(x, y, 3) * a + 127) / 255);
    }
  return out;
}

std::string PercentDecode(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uint8_t(uri[i + 1])) &&
        std::isxdigit(uint8_t(uri[i + 2]))) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

}  // namespace voltree
