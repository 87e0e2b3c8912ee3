// Texture decoding and alpha handling shared by the glTF and OBJ importers: everything ends as
// RGBA8 with straight alpha, colours sRGB as stored in the file.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "core/image.h"

namespace voltree {

// Decodes an encoded image (PNG, JPEG, ...) held in memory. `format_hint` is a MIME type
// ("image/png") or a file name whose extension names the format; the magic bytes win when they
// are recognised. `what` names the image in errors. Throws Error when it cannot be decoded.
Image8 DecodeImageRgba8(std::span<const uint8_t> bytes, const std::string& format_hint, const std::string& what);

// Reads an image file as RGBA8 straight alpha (grey and RGB gain an opaque alpha).
Image8 ReadImageRgba8(const std::filesystem::path& path);

// Grey, grey+alpha, RGB or RGBA -> RGBA, alpha 255 where the source has none.
Image8 ToRgba8(const Image8& image);

// True when some texel of an RGBA image is not fully opaque.
bool HasTransparency(const Image8& rgba);

// The coverage an OBJ `map_d` texture stands for: its alpha channel when it has a non-opaque
// one (an RGBA cut-out), else its first channel (a grey mask). One channel, source size.
Image8 CoverageFromAlphaMap(const Image8& alpha_map);

// `colour` (RGBA) with its alpha multiplied by `coverage` (one channel), which is resampled
// bilinearly when the sizes differ, so a map_d of another resolution still lines up.
Image8 MultiplyAlpha(const Image8& colour, const Image8& coverage);

// "leaf%20a.png" -> "leaf a.png" (glTF URIs are percent-encoded).
std::string PercentDecode(const std::string& uri);

}  // namespace voltree
