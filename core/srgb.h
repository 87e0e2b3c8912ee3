// The sRGB transfer curve (IEC 61966-2-1), shared by the studio's shading and CIELab conversion.
#pragma once

namespace voltree {

// sRGB-encoded component in [0, 1] -> linear light, and back.
float SrgbToLinear(float encoded);
float LinearToSrgb(float linear);

}  // namespace voltree
