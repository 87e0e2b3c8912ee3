// WriteVolume / ReadVolume: round trip, corruption detection, refusal to overwrite.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/crc32.h"
#include "core/error.h"
#include "core/files.h"
#include "core/volume_io.h"
#include "temp_dir.h"

namespace voltree {
namespace {
namespace fs = std::filesystem;

Volume SmallVolume() {
  Volume v;
  v.origin = {-1, -2, 0.5};
  v.size = 3.25;
  v.branching = 2;
  v.texels = 2;
  v.views = {VolumeView{"a.png", {1, 2, 3}, {0, 0, 1}, {0, 1, 0}},
             VolumeView{"b.png", {4, 5, 6}, {1, 0, 0}, {0, 0, 1}}};
  v.levels.resize(2);
  v.levels[0].resolution = 1;
  v.levels[0].cells = {{0, 0, 0}};
  v.levels[0].density = {0.5f};
  v.levels[0].billboards = {{0, 0}, {0, 1}};
  v.levels[0].texels.assign(2 * 16, 0);
  for (size_t i = 0; i < v.levels[0].texels.size(); ++i) v.levels[0].texels[i] = uint8_t(i * 7);
  v.levels[0].billboards_before_pruning = 2;
  v.levels[1].resolution = 2;
  v.levels[1].cells = {{1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
  v.levels[1].density = {0.25f, 1.5f, 0.0f};
  v.levels[1].billboards = {{1, 1}};
  v.levels[1].texels.assign(16, 200);
  v.levels[1].billboards_before_pruning = 6;
  return v;
}

void ExpectSame(const Volume& a, const Volume& b) {
  EXPECT_EQ(EncodeVolumeBinary(a), EncodeVolumeBinary(b));
  EXPECT_EQ(VolumeJson(a, {}).dump(), VolumeJson(b, {}).dump());
}

TEST(VolumeIo, RoundTripsEveryField) {
  testing::TempDir dir("io_roundtrip");
  const Volume volume = SmallVolume();
  WriteVolume(dir.path / "volume", volume, {{"note", "test"}});
  const Volume read = ReadVolume(dir.path / "volume");
  ExpectSame(volume, read);
  EXPECT_EQ(read.views[1].name, "b.png");
  EXPECT_EQ(read.levels[1].billboards_before_pruning, 6u);
  EXPECT_DOUBLE_EQ(PrunedPercent(read.levels[1]), 100.0 * 5 / 6);
}

TEST(VolumeIo, RefusesToOverwriteWithoutForce) {
  testing::TempDir dir("io_force");
  WriteVolume(dir.path / "volume", SmallVolume());
  EXPECT_THROW(WriteVolume(dir.path / "volume", SmallVolume()), Error);
  EXPECT_NO_THROW(WriteVolume(dir.path / "volume", SmallVolume(), {}, true));
}

TEST(VolumeIo, InvalidVolumeWritesNothing) {
  testing::TempDir dir("io_invalid");
  Volume volume = SmallVolume();
  volume.levels[1].billboards[0].cell = 7;  // no such cell
  EXPECT_THROW(WriteVolume(dir.path / "volume", volume), Error);
  EXPECT_FALSE(fs::exists(dir.path / "volume"));
  EXPECT_TRUE(fs::is_empty(dir.path));
}

std::string LoadErrorOf(const fs::path& folder) {
  try {
    ReadVolume(folder);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(VolumeIo, DetectsCorruptionAndNamesTheFile) {
  testing::TempDir dir("io_corrupt");
  const fs::path folder = dir.path / "volume";
  WriteVolume(folder, SmallVolume());
  const std::string good = ReadFile(folder / kVolumeBinName);

  std::string flipped = good;
  flipped[40] ^= 0x10;
  WriteFileAtomic(folder / kVolumeBinName, flipped);
  EXPECT_NE(LoadErrorOf(folder).find("volume.bin: checksum"), std::string::npos) << LoadErrorOf(folder);

  WriteFileAtomic(folder / kVolumeBinName, good.substr(0, 30));
  EXPECT_NE(LoadErrorOf(folder).find("volume.bin"), std::string::npos);

  std::string magic = good;
  magic[0] = 'X';
  WriteFileAtomic(folder / kVolumeBinName, magic);
  EXPECT_NE(LoadErrorOf(folder).find("bad magic"), std::string::npos);

  WriteFileAtomic(folder / kVolumeBinName, good);
  WriteFileAtomic(folder / kVolumeJsonName, "{\"format\": \"voltree-volume\"");
  EXPECT_NE(LoadErrorOf(folder).find("volume.json: not valid JSON"), std::string::npos) << LoadErrorOf(folder);
}

// `bytes` without its checksum, re-checksummed as volume.bin is.
std::string WithCrc(std::string bytes) {
  const uint32_t crc = Crc32(bytes.data(), bytes.size());
  for (int i = 0; i < 4; ++i) bytes.push_back(char((crc >> (8 * i)) & 0xFF));
  return bytes;
}

TEST(VolumeIo, ChecksCountsEvenWithAValidChecksum) {
  // A level count that promises more cells than the file holds, re-checksummed.
  Volume volume = SmallVolume();
  std::string bytes = EncodeVolumeBinary(volume);
  bytes.resize(bytes.size() - 4);
  const size_t cells_field = 8 + 4 * 5 + 4;                                   // magic, header, level 0 resolution
  for (int i = 0; i < 8; ++i) bytes[cells_field + i] = char(i == 5 ? 1 : 0);  // 2^40, little-endian
  testing::TempDir dir("io_counts");
  WriteVolume(dir.path / "volume", volume);
  WriteFileAtomic(dir.path / "volume" / kVolumeBinName, WithCrc(bytes));
  EXPECT_NE(LoadErrorOf(dir.path / "volume").find("exceed the file size"), std::string::npos)
      << LoadErrorOf(dir.path / "volume");
}

TEST(VolumeIo, EndsWithTheCrc32OfEverythingBefore) {
  const std::string bytes = EncodeVolumeBinary(SmallVolume());
  EXPECT_EQ(bytes, WithCrc(bytes.substr(0, bytes.size() - 4)));
  EXPECT_EQ(bytes.substr(8, 4), std::string("\x02\0\0\0", 4));  // version 2, little-endian
}

// A volume as version 1 wrote it: version 1 in both files, FNV-1a 64 at the end of volume.bin.
void WriteVersion1(const fs::path& folder) {
  WriteVolume(folder, SmallVolume());
  std::string json = ReadFile(folder / kVolumeJsonName);
  const size_t version = json.find("\"version\": 2");
  ASSERT_NE(version, std::string::npos) << json;
  json.replace(version, 12, "\"version\": 1");
  WriteFileAtomic(folder / kVolumeJsonName, json);
  std::string bytes = EncodeVolumeBinary(SmallVolume());
  bytes.resize(bytes.size() - 4);
  bytes[8] = 1;
  uint64_t hash = 1469598103934665603ull;
  for (char c : bytes) hash = (hash ^ uint8_t(c)) * 1099511628211ull;
  for (int i = 0; i < 8; ++i) bytes.push_back(char((hash >> (8 * i)) & 0xFF));
  WriteFileAtomic(folder / kVolumeBinName, bytes);
}

TEST(VolumeIo, AnOlderVersionAsksToReconstructAgain) {
  testing::TempDir dir("io_version");
  const fs::path folder = dir.path / "volume";
  WriteVersion1(folder);
  const std::string message = LoadErrorOf(folder);
  EXPECT_NE(message.find("volume.json: volume version 1 was written by an older voltree; run 'voltree reconstruct' "
                         "again"),
            std::string::npos)
      << message;

  // volume.bin alone of version 1 says the same, not that its checksum is wrong.
  WriteFileAtomic(folder / kVolumeJsonName, VolumeJson(SmallVolume(), {}).dump(2));
  const std::string bin_message = LoadErrorOf(folder);
  EXPECT_NE(bin_message.find("volume.bin: volume version 1 was written by an older voltree"), std::string::npos)
      << bin_message;

  // A version from the future is not blamed on an older voltree.
  std::string bytes = EncodeVolumeBinary(SmallVolume());
  bytes[8] = 3;
  WriteFileAtomic(folder / kVolumeBinName, bytes);
  EXPECT_NE(LoadErrorOf(folder).find("volume.bin: unsupported volume version 3"), std::string::npos)
      << LoadErrorOf(folder);
}

}  // namespace
}  // namespace voltree
