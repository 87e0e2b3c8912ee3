#include "core/volume_io.h"

#include <cmath>
#include <cstring>
#include <string_view>

#include "core/byte_reader.h"
#include "core/byte_writer.h"
#include "core/crc32.h"
#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'V', 'T', 'V', 'O', 'L', 'B', 'I', 'N'};
// 2: CRC-32 (as .vtree) instead of FNV-1a 64 at the end of volume.bin.
constexpr uint32_t kVersion = 2;

// A volume of another version, seen in either of its files: the way out is to reconstruct again.
[[noreturn]] void UnsupportedVersion(const std::string& file, int64_t version) {
  if (version >= 1 && version < int64_t(kVersion))
    Fail(file, ": volume version ", version,
         " was written by an older voltree; run 'voltree reconstruct' again "
         "(with --force to replace the volume; this build reads version ",
         kVersion, ")");
  Fail(file, ": unsupported volume version ", version, " (this build reads version ", kVersion, ")");
}

uint64_t Resolution(int branching, int level) {
  uint64_t r = 1;
  for (int i = 0; i < level; ++i) r *= branching;
  return r;
}

nlohmann::json Vec(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

Eigen::Vector3d VecFrom(const nlohmann::json& j, const std::string& file, const char* field) {
  if (!j.is_array() || j.size() != 3) Fail(file, ": field '", field, "' must be an array of 3 numbers");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number()) Fail(file, ": field '", field, "' must be an array of 3 numbers");
    v[i] = j[i].get<double>();
  }
  return v;
}

}  // namespace

double PrunedPercent(const VolumeLevel& level) {
  if (level.billboards_before_pruning == 0) return 0;
  return 100.0 * double(level.billboards_before_pruning - level.billboards.size()) /
         double(level.billboards_before_pruning);
}

void CheckVolume(const Volume& volume, const std::string& where) {
  if (volume.branching != 2 && volume.branching != 3) Fail(where, ": branching must be 2 or 3, got ", volume.branching);
  if (volume.texels < 1 || volume.texels > 64) Fail(where, ": texels must be in [1, 64], got ", volume.texels);
  if (!(volume.size > 0) || !std::isfinite(volume.size)) Fail(where, ": root cube size must be positive");
  if (volume.views.size() > 65535) Fail(where, ": at most 65535 views, got ", volume.views.size());
  const size_t texel_bytes = volume.BytesPerBillboard();
  for (size_t l = 0; l < volume.levels.size(); ++l) {
    const VolumeLevel& level = volume.levels[l];
    const uint64_t resolution = Resolution(volume.branching, int(l));
    if (uint64_t(level.resolution) != resolution)
      Fail(where, ": level ", l, " has resolution ", level.resolution, ", expected ", resolution);
    if (level.density.size() != level.cells.size())
      Fail(where, ": level ", l, " has ", level.cells.size(), " cells but ", level.density.size(), " densities");
    if (level.texels.size() != level.billboards.size() * texel_bytes)
      Fail(where, ": level ", l, " has ", level.billboards.size(), " billboards but ", level.texels.size(),
           " texel bytes, expected ", level.billboards.size() * texel_bytes);
    if (level.billboards_before_pruning < level.billboards.size())
      Fail(where, ": level ", l, " has more billboards after pruning than before");
    for (size_t i = 0; i < level.cells.size(); ++i) {
      const auto& c = level.cells[i];
      if (c[0] >= resolution || c[1] >= resolution || c[2] >= resolution)
        Fail(where, ": level ", l, " cell ", i, " lies outside the ", resolution, "^3 grid");
      if (i > 0) {
        const auto& p = level.cells[i - 1];
        if (std::array{p[2], p[1], p[0]} >= std::array{c[2], c[1], c[0]})
          Fail(where, ": level ", l, " cells are not sorted by (z, y, x) without duplicates at cell ", i);
      }
      if (!(level.density[i] >= 0) || !std::isfinite(level.density[i]))
        Fail(where, ": level ", l, " cell ", i, " has density ", level.density[i], ", expected a finite value >= 0");
    }
    for (size_t i = 0; i < level.billboards.size(); ++i) {
      const Billboard& b = level.billboards[i];
      if (b.cell >= level.cells.size())
        Fail(where, ": level ", l, " billboard ", i, " refers to cell ", b.cell, " of ", level.cells.size());
      if (b.view >= volume.views.size())
        Fail(where, ": level ", l, " billboard ", i, " refers to view ", b.view, " of ", volume.views.size());
      if (i > 0) {
        const Billboard& p = level.billboards[i - 1];
        if (std::pair{p.cell, p.view} >= std::pair{b.cell, b.view})
          Fail(where, ": level ", l, " billboards are not sorted by (cell, view) without duplicates at ", i);
      }
    }
  }
}

std::string EncodeVolumeBinary(const Volume& volume) {
  ByteWriter out;
  out.Bytes(kMagic, sizeof(kMagic));
  out.Le(kVersion);
  out.Le(uint32_t(volume.texels));
  out.Le(uint32_t(volume.branching));
  out.Le(uint32_t(volume.levels.size()));
  out.Le(uint32_t(volume.views.size()));
  for (const VolumeLevel& level : volume.levels) {
    out.Le(uint32_t(level.resolution));
    out.Le(uint64_t(level.cells.size()));
    out.Le(uint64_t(level.billboards.size()));
    out.Le(uint64_t(level.billboards_before_pruning));
  }
  for (const VolumeLevel& level : volume.levels) {
    for (const auto& c : level.cells) out.Array<uint16_t>(c);
    out.Array<float>(level.density);
    for (const Billboard& b : level.billboards) {
      out.Le(b.cell);
      out.Le(b.view);
    }
    out.Array<uint8_t>(level.texels);
  }
  out.Le(Crc32(out.bytes().data(), out.bytes().size()));
  return out.Take();
}

nlohmann::json VolumeJson(const Volume& volume, const nlohmann::json& provenance) {
  nlohmann::json doc;
  doc["format"] = "voltree-volume";
  doc["version"] = kVersion;
  doc["data"] = kVolumeBinName;
  doc["origin"] = Vec(volume.origin);
  doc["size"] = volume.size;
  doc["branching"] = volume.branching;
  doc["texels"] = volume.texels;
  nlohmann::json views = nlohmann::json::array();
  for (const VolumeView& v : volume.views)
    views.push_back(
        {{"name", v.name}, {"position", Vec(v.position)}, {"direction", Vec(v.direction)}, {"up", Vec(v.up)}});
  doc["views"] = views;
  nlohmann::json levels = nlohmann::json::array();
  for (size_t l = 0; l < volume.levels.size(); ++l) {
    const VolumeLevel& level = volume.levels[l];
    levels.push_back({{"level", l},
                      {"resolution", level.resolution},
                      {"cells", level.cells.size()},
                      {"billboards_before_pruning", level.billboards_before_pruning},
                      {"billboards", level.billboards.size()},
                      {"pruned_percent", PrunedPercent(level)},
                      {"texel_bytes", level.texels.size()}});
  }
  doc["levels"] = levels;
  doc["provenance"] = provenance;
  return doc;
}

void WriteVolume(const fs::path& folder, const Volume& volume, const nlohmann::json& provenance, bool force) {
  CheckVolume(volume, folder.string());
  const std::string binary = EncodeVolumeBinary(volume);
  const std::string json = VolumeJson(volume, provenance).dump(2) + "\n";
  StagedDirectory staged(folder, force);
  WriteFileAtomic(staged.path() / kVolumeBinName, binary);
  WriteFileAtomic(staged.path() / kVolumeJsonName, json);
  staged.Commit();
}

Volume ReadVolume(const fs::path& folder) {
  const fs::path json_path = folder / kVolumeJsonName;
  const fs::path bin_path = folder / kVolumeBinName;
  const std::string json_file = json_path.string();
  const std::string bin_file = bin_path.string();
  if (!fs::is_directory(folder))
    Fail(folder.string(), ": no such folder (expected a volume written by 'voltree reconstruct')");

  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(ReadFile(json_path));
  } catch (const nlohmann::json::exception& e) {
    Fail(json_file, ": not valid JSON: ", e.what());
  }
  Volume volume;
  try {
    if (doc.value("format", "") != "voltree-volume") Fail(json_file, ": field 'format' must be \"voltree-volume\"");
    if (const int version = doc.at("version").get<int>(); version != int(kVersion))
      UnsupportedVersion(json_file, version);
    volume.origin = VecFrom(doc.at("origin"), json_file, "origin");
    volume.size = doc.at("size").get<double>();
    volume.branching = doc.at("branching").get<int>();
    volume.texels = doc.at("texels").get<int>();
    for (const auto& v : doc.at("views")) {
      VolumeView view;
      view.name = v.at("name").get<std::string>();
      view.position = VecFrom(v.at("position"), json_file, "views[].position");
      view.direction = VecFrom(v.at("direction"), json_file, "views[].direction");
      view.up = VecFrom(v.at("up"), json_file, "views[].up");
      volume.views.push_back(view);
    }
  } catch (const nlohmann::json::exception& e) {
    Fail(json_file, ": missing or mistyped field: ", e.what());
  }

  const std::string bytes = ReadFile(bin_path);
  if (bytes.size() < sizeof(kMagic) + 8) Fail(bin_file, ": too short (", bytes.size(), " bytes) to be a volume");
  if (std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) Fail(bin_file, ": bad magic, expected \"VTVOLBIN\"");
  // The version before the checksum: an older file has another checksum and deserves the better message.
  const std::string_view payload = std::string_view(bytes).substr(0, bytes.size() - sizeof(uint32_t));
  ByteReader in(payload, bin_file);
  in.Take(sizeof(kMagic), "the magic");
  if (const uint32_t version = in.U32("the version"); version != kVersion) UnsupportedVersion(bin_file, version);
  ByteReader checksum(std::string_view(bytes).substr(payload.size()), bin_file);
  if (checksum.U32("the checksum") != Crc32(payload.data(), payload.size()))
    Fail(bin_file, ": checksum mismatch (file is corrupt)");

  const uint32_t texels = in.U32("texels");
  const uint32_t branching = in.U32("branching");
  const uint32_t level_count = in.U32("the level count");
  const uint32_t view_count = in.U32("the view count");
  if (int(texels) != volume.texels || int(branching) != volume.branching || view_count != volume.views.size())
    Fail(bin_file, ": header (texels ", texels, ", branching ", branching, ", views ", view_count, ") disagrees with ",
         json_file, " (texels ", volume.texels, ", branching ", volume.branching, ", views ", volume.views.size(), ")");
  if (level_count > 32) Fail(bin_file, ": level count ", level_count, " is implausible (expected at most 32)");
  const size_t texel_bytes = volume.BytesPerBillboard();
  volume.levels.resize(level_count);
  for (VolumeLevel& level : volume.levels) {
    level.resolution = int(in.U32("a level resolution"));
    const uint64_t cells = in.U64("a level cell count");
    const uint64_t billboards = in.U64("a level billboard count");
    level.billboards_before_pruning = in.U64("a level billboard count before pruning");
    // Counts are checked against the bytes left before anything is allocated.
    if (cells > in.remaining() / 10 || billboards > in.remaining() / (6 + texel_bytes))
      Fail(bin_file, ": level counts (", cells, " cells, ", billboards, " billboards) exceed the file size");
    level.cells.resize(cells);
    level.density.resize(cells);
    level.billboards.resize(billboards);
    level.texels.resize(billboards * texel_bytes);
  }
  for (VolumeLevel& level : volume.levels) {
    for (auto& c : level.cells) in.Array<uint16_t>(c, "cell coordinates");
    in.Array<float>(level.density, "densities");
    for (Billboard& b : level.billboards) {
      b.cell = in.U32("a billboard cell");
      b.view = in.U16("a billboard view");
    }
    in.Array<uint8_t>(level.texels, "texels");
  }
  if (in.remaining() != 0) Fail(bin_file, ": ", in.remaining(), " unexpected bytes after the last level");
  CheckVolume(volume, bin_file);
  return volume;
}

}  // namespace voltree
