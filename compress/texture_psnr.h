// PSNR of reconstructed billboard textures against the originals, over all four premultiplied
// RGBA8 channels (the error the renderer composites), as in Linz 2006 Fig. 6.
#pragma once

#include <cstdint>
#include <vector>

namespace voltree {

double MeanSquaredError(const std::vector<uint8_t>& reference, const std::vector<uint8_t>& test);
// 10 log10(255^2 / MSE); +infinity for identical inputs.
double Psnr(const std::vector<uint8_t>& reference, const std::vector<uint8_t>& test);

}  // namespace voltree
