// Decompression-bomb guard: a tiny file may declare billions of pixels. Photos are checked against
// a cap and against the memory this machine has free before a single pixel is decoded.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace voltree {

// The largest photo voltree decodes: 2^28 pixels (16384 x 16384), far above any camera's and
// 4 GiB as 8-bit RGBA with the copies ReadImage8 makes.
constexpr int64_t kMaxImagePixels = int64_t(1) << 28;

// Bytes decoding needs: the decoded buffer plus one converted copy (orientation, channels).
int64_t DecodeBytes(int64_t width, int64_t height, int channels, int bytes_per_channel);

// Why an image of this declared size must not be decoded, or nothing when it may be.
// `available_bytes` is the free memory (nullopt when unknown).
std::optional<std::string> ImageSizeProblem(int64_t width, int64_t height, int channels, int bytes_per_channel,
                                            std::optional<int64_t> available_bytes);

// MemAvailable of /proc/meminfo, or nullopt where there is none.
std::optional<int64_t> FreeMemoryBytes();

// Throws Error naming `path` when ImageSizeProblem finds one.
void CheckImageSizeBeforeDecoding(const std::filesystem::path& path, int64_t width, int64_t height, int channels,
                                  int bytes_per_channel);

}  // namespace voltree
