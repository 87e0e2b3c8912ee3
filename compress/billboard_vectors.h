// Training vectors from the billboards of a Volume (all levels, in level then billboard order):
// colour vectors of n*n texels x 3 components from UN-premultiplied colour (so that a texel's
// colour does not depend on its opacity), and alpha vectors of n*n components, quantized apart.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compress/training_set.h"
#include "core/volume.h"

namespace voltree {

enum class ColourSpace { kLab, kRgb };
ColourSpace ParseColourSpace(const std::string& name);  // "lab" | "rgb"
std::string ColourSpaceName(ColourSpace space);

// Every billboard's premultiplied RGBA8 texels, concatenated over the levels.
std::vector<uint8_t> GatherTexels(const Volume& volume);
size_t CountBillboards(const Volume& volume);

// Colour vectors. Lab: (L*, a*, b*); RGB: sRGB values in [0, 255]. A fully transparent texel has
// no colour; it takes the alpha-weighted mean colour of its billboard so it adds no spurious
// variance. With `alpha_weighted`, each component is weighted by its texel's alpha in [0, 1]:
// the colour of a texel nobody sees then does not matter to the codebook.
TrainingSet ColourVectors(const std::vector<uint8_t>& texels, int texel_count, ColourSpace space, bool alpha_weighted);
// Alpha vectors in [0, 255].
TrainingSet AlphaVectors(const std::vector<uint8_t>& texels, int texel_count);

// Codewords back to 8-bit: colour codebook -> K x texel_count x RGB (straight sRGB), alpha -> K x texel_count.
std::vector<uint8_t> DecodeColourCodebook(const Codebook& codebook, ColourSpace space);
std::vector<uint8_t> DecodeAlphaCodebook(const Codebook& codebook);

}  // namespace voltree
