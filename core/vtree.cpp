#include "core/vtree.h"

#include <zstd.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/byte_reader.h"
#include "core/byte_writer.h"
#include "core/crc32.h"
#include "core/error.h"
#include "core/files.h"

namespace voltree {
namespace {

using nlohmann::json;

constexpr char kMagic[8] = {'V', 'T', 'R', 'E', 'E', 0, 0, 0};
constexpr size_t kChunkHeaderBytes = 4 + 4 + 8 + 8 + 4;
constexpr uint32_t kRaw = 0, kZstd = 1;
constexpr size_t kCellBytes = 3 * 2 + 4;  // coordinates + density
constexpr size_t kBillboardBytes = 4 + 2 + 2 + 2;
constexpr uint32_t kMaxLevels = 17;        // 2^16 cells per axis fit u16 coordinates
constexpr uint32_t kMaxAtlasSide = 16384;  // GL_MAX_TEXTURE_SIZE on every current driver

// ---- writing ----

uint32_t ChunkCrc(std::string_view header_fields, std::string_view payload) {
  return Crc32(payload.data(), payload.size(), Crc32(header_fields.data(), header_fields.size()));
}

void AppendChunk(ByteWriter& file, const char (&tag)[5], const std::string& raw, bool zstd, int level) {
  std::string stored = raw;
  uint32_t encoding = kRaw;
  if (zstd) {
    stored.resize(ZSTD_compressBound(raw.size()));
    const size_t size = ZSTD_compress(stored.data(), stored.size(), raw.data(), raw.size(), level);
    if (ZSTD_isError(size)) Fail("zstd: ", ZSTD_getErrorName(size));
    stored.resize(size);
    encoding = kZstd;
  }
  ByteWriter header;
  header.Bytes(tag, 4);
  header.Le<uint32_t>(encoding);
  header.Le<uint64_t>(stored.size());
  header.Le<uint64_t>(raw.size());
  const uint32_t crc = ChunkCrc(header.bytes(), stored);
  file.Bytes(header.bytes());
  file.Le<uint32_t>(crc);
  file.Bytes(stored);
}

json Vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

std::string HeaderJson(const VtreeAsset& asset) {
  json views = json::array();
  for (const auto& view : asset.views)
    views.push_back({{"name", view.name},
                     {"position", Vec(view.position)},
                     {"direction", Vec(view.direction)},
                     {"up", Vec(view.up)}});
  const json header = {
      {"format", "voltree"},
      {"levels", asset.levels.size()},
      {"branching", asset.branching},
      {"texels", asset.texels},
      {"root_origin", Vec(asset.origin)},
      {"root_size", asset.size},
      {"bounds_min", Vec(asset.bounds_min)},
      {"bounds_max", Vec(asset.bounds_max)},
      {"views", views},
      {"codebooks",
       {{"colour", asset.colour_codebook_size},
        {"alpha", asset.alpha_codebook_size},
        {"colour_space", asset.colour_space}}},
      {"atlas", {{"format", "DXT5"}, {"colour", "straight sRGB"}}},
      {"provenance", asset.provenance},
  };
  return header.dump(1);  // std::map keys: sorted, so the bytes are deterministic
}

std::string CellPayload(const VtreeLevel& level, uint32_t index) {
  ByteWriter out;
  out.Le<uint32_t>(index);
  out.Le<uint32_t>(level.resolution);
  out.Le<uint32_t>(static_cast<uint32_t>(level.cells.size()));
  for (const auto& cell : level.cells)
    for (uint16_t c : cell) out.Le(c);
  for (float d : level.density) out.F32(d);
  return out.Take();
}

std::string BillboardPayload(const VtreeLevel& level, uint32_t index) {
  ByteWriter out;
  out.Le<uint32_t>(index);
  out.Le<uint64_t>(level.billboards_before_pruning);
  out.Le<uint32_t>(static_cast<uint32_t>(level.billboards.size()));
  for (const auto& b : level.billboards) {
    out.Le(b.cell);
    out.Le(b.view);
    out.Le(b.colour);
    out.Le(b.alpha);
  }
  return out.Take();
}

std::string AtlasPayload(const VtreeAtlas& atlas) {
  ByteWriter out;
  out.Le(atlas.width);
  out.Le(atlas.height);
  out.Le(atlas.tile_pitch);
  out.Le(atlas.tiles_per_row);
  out.Le(atlas.tile_count);
  out.Bytes(atlas.dxt5.data(), atlas.dxt5.size());
  return out.Take();
}

// ---- reading ----

struct Chunk {
  std::string tag;
  uint64_t offset = 0;  // of the chunk header in the file
  uint32_t encoding = kRaw;
  uint64_t stored_size = 0, raw_size = 0;
  uint32_t crc = 0;
  std::string_view stored;
};

std::string TagText(std::string_view tag) {
  std::string text;
  for (char c : tag) text += (c >= 32 && c < 127) ? c : '?';
  return text;
}

Chunk ReadChunkHeader(ByteReader& file) {
  Chunk chunk;
  chunk.offset = file.offset();
  chunk.tag = std::string(file.Take(4, "chunk tag"));
  chunk.encoding = file.Le<uint32_t>("chunk encoding");
  chunk.stored_size = file.Le<uint64_t>("chunk size");
  chunk.raw_size = file.Le<uint64_t>("chunk raw size");
  chunk.crc = file.Le<uint32_t>("chunk checksum");
  if (chunk.stored_size > file.remaining())
    file.Fail("chunk ", TagText(chunk.tag), " at byte ", chunk.offset, ": truncated, its payload needs ",
              chunk.stored_size, " bytes but only ", file.remaining(), " remain");
  chunk.stored = file.Take(chunk.stored_size, "chunk payload");
  return chunk;
}

std::string ChunkContext(const std::string& name, const Chunk& chunk) {
  return Str(name, ": chunk ", TagText(chunk.tag), " at byte ", chunk.offset);
}

std::string Unpack(const Chunk& chunk, const std::string& name, const VtreeReadOptions& options) {
  const std::string context = ChunkContext(name, chunk);
  if (options.verify_checksums) {
    ByteWriter header;
    header.Bytes(chunk.tag.data(), 4);
    header.Le(chunk.encoding);
    header.Le(chunk.stored_size);
    header.Le(chunk.raw_size);
    if (ChunkCrc(header.bytes(), chunk.stored) != chunk.crc) Fail(context, ": checksum mismatch");
  }
  if (chunk.raw_size > kVtreeMaxChunkBytes)
    Fail(context, ": raw size ", chunk.raw_size, " exceeds the limit of ", kVtreeMaxChunkBytes, " bytes");
  if (chunk.encoding == kRaw) {
    if (chunk.raw_size != chunk.stored_size)
      Fail(context, ": raw size ", chunk.raw_size, " differs from stored size ", chunk.stored_size);
    return std::string(chunk.stored);
  }
  if (chunk.encoding != kZstd) Fail(context, ": unknown encoding ", chunk.encoding, " (expected 0 raw or 1 zstd)");
  const unsigned long long content = ZSTD_getFrameContentSize(chunk.stored.data(), chunk.stored.size());
  if (content != chunk.raw_size) Fail(context, ": zstd frame does not declare the expected ", chunk.raw_size, " bytes");
  std::string raw(chunk.raw_size, '\0');
  const size_t size = ZSTD_decompress(raw.data(), raw.size(), chunk.stored.data(), chunk.stored.size());
  if (ZSTD_isError(size)) Fail(context, ": zstd: ", ZSTD_getErrorName(size));
  if (size != chunk.raw_size) Fail(context, ": zstd gave ", size, " bytes, expected ", chunk.raw_size);
  return raw;
}

// ---- header fields ----

template <typename T>
T Field(const json& object, const char* key, const std::string& context) {
  const auto it = object.find(key);
  if (it == object.end()) Fail(context, ": missing field '", key, "'");
  try {
    return it->get<T>();
  } catch (const json::exception&) {
    Fail(context, ": field '", key, "' has the wrong type");
  }
}

double FiniteField(const json& object, const char* key, const std::string& context) {
  const auto value = Field<double>(object, key, context);
  if (!std::isfinite(value)) Fail(context, ": field '", key, "' is not finite");
  return value;
}

int64_t IntField(const json& object, const char* key, int64_t low, int64_t high, const std::string& context) {
  const auto it = object.find(key);
  if (it == object.end()) Fail(context, ": missing field '", key, "'");
  if (!it->is_number_integer()) Fail(context, ": field '", key, "' must be an integer");
  const int64_t value =
      it->is_number_unsigned() && it->get<uint64_t>() > uint64_t(INT64_MAX) ? INT64_MAX : it->get<int64_t>();
  if (value < low || value > high)
    Fail(context, ": field '", key, "' = ", value, " is out of range [", low, ", ", high, "]");
  return value;
}

Eigen::Vector3d VecField(const json& object, const char* key, const std::string& context) {
  const auto it = object.find(key);
  if (it == object.end()) Fail(context, ": missing field '", key, "'");
  if (!it->is_array() || it->size() != 3) Fail(context, ": field '", key, "' must be an array of 3 numbers");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!(*it)[i].is_number() || !std::isfinite((*it)[i].get<double>()))
      Fail(context, ": field '", key, "' must be an array of 3 finite numbers");
    v[i] = (*it)[i].get<double>();
  }
  return v;
}

void ParseHeader(const std::string& text, const std::string& context, VtreeAsset& asset, uint32_t& level_count) {
  const json header = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (header.is_discarded() || !header.is_object()) Fail(context, ": header is not a JSON object");
  if (Field<std::string>(header, "format", context) != "voltree") Fail(context, ": field 'format' is not 'voltree'");
  level_count = static_cast<uint32_t>(IntField(header, "levels", 1, kMaxLevels, context));
  asset.branching = static_cast<int>(IntField(header, "branching", 2, 3, context));
  asset.texels = static_cast<int>(IntField(header, "texels", 1, 64, context));
  asset.origin = VecField(header, "root_origin", context);
  asset.size = FiniteField(header, "root_size", context);
  if (!(asset.size > 0)) Fail(context, ": field 'root_size' must be positive");
  asset.bounds_min = VecField(header, "bounds_min", context);
  asset.bounds_max = VecField(header, "bounds_max", context);
  const auto views = header.find("views");
  if (views == header.end() || !views->is_array()) Fail(context, ": field 'views' must be an array");
  if (views->size() > 65535) Fail(context, ": ", views->size(), " views exceed the limit of 65535");
  for (size_t i = 0; i < views->size(); ++i) {
    const std::string view_context = Str(context, ": views[", i, "]");
    const json& item = (*views)[i];
    if (!item.is_object()) Fail(view_context, ": expected an object");
    VtreeView view;
    view.name = Field<std::string>(item, "name", view_context);
    view.position = VecField(item, "position", view_context);
    view.direction = VecField(item, "direction", view_context);
    view.up = VecField(item, "up", view_context);
    asset.views.push_back(std::move(view));
  }
  const auto codebooks = header.find("codebooks");
  if (codebooks == header.end() || !codebooks->is_object()) Fail(context, ": field 'codebooks' must be an object");
  const std::string codebook_context = context + ": codebooks";
  asset.colour_codebook_size = static_cast<uint32_t>(IntField(*codebooks, "colour", 1, 65536, codebook_context));
  asset.alpha_codebook_size = static_cast<uint32_t>(IntField(*codebooks, "alpha", 1, 65536, codebook_context));
  asset.colour_space = Field<std::string>(*codebooks, "colour_space", codebook_context);
  const auto provenance = header.find("provenance");
  if (provenance != header.end()) asset.provenance = *provenance;
}

VtreeLevel ParseCells(const std::string& payload, const std::string& context, uint32_t index,
                      uint32_t expected_resolution) {
  ByteReader in(payload, context);
  VtreeLevel level;
  if (const auto stored = in.Le<uint32_t>("level index"); stored != index)
    in.Fail("level index ", stored, ", expected ", index);
  level.resolution = in.Le<uint32_t>("resolution");
  if (level.resolution != expected_resolution)
    in.Fail("resolution ", level.resolution, ", expected ", expected_resolution, " (branching^level)");
  const uint32_t count = in.Le<uint32_t>("cell count");
  if (in.remaining() / kCellBytes < count || in.remaining() != size_t(count) * kCellBytes)
    in.Fail("cell count ", count, " needs ", size_t(count) * kCellBytes, " bytes, the chunk has ", in.remaining());
  const uint64_t total_cells = uint64_t(level.resolution) * level.resolution * level.resolution;
  if (count > total_cells) in.Fail("cell count ", count, " exceeds ", total_cells, " cells of the grid");
  level.cells.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    for (auto& c : level.cells[i]) {
      c = in.Le<uint16_t>("cell coordinate");
      if (c >= level.resolution) in.Fail("cell ", i, " coordinate ", c, " out of range [0, ", level.resolution, ")");
    }
  }
  level.density.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    level.density[i] = in.F32("density");
    if (!(level.density[i] >= 0) || !std::isfinite(level.density[i]))
      in.Fail("cell ", i, " density ", level.density[i], " is not finite and >= 0");
  }
  return level;
}

void ParseBillboards(const std::string& payload, const std::string& context, uint32_t index, const VtreeAsset& asset,
                     VtreeLevel& level) {
  ByteReader in(payload, context);
  if (const auto stored = in.Le<uint32_t>("level index"); stored != index)
    in.Fail("level index ", stored, ", expected ", index);
  level.billboards_before_pruning = in.Le<uint64_t>("billboards before pruning");
  const uint32_t count = in.Le<uint32_t>("billboard count");
  if (in.remaining() / kBillboardBytes < count || in.remaining() != size_t(count) * kBillboardBytes)
    in.Fail("billboard count ", count, " needs ", size_t(count) * kBillboardBytes, " bytes, the chunk has ",
            in.remaining());
  level.billboards.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    auto& b = level.billboards[i];
    b.cell = in.Le<uint32_t>("billboard cell");
    b.view = in.Le<uint16_t>("billboard view");
    b.colour = in.Le<uint16_t>("billboard colour index");
    b.alpha = in.Le<uint16_t>("billboard alpha index");
    if (b.cell >= level.cells.size())
      in.Fail("billboard ", i, ": cell ", b.cell, " out of range [0, ", level.cells.size(), ")");
    if (b.view >= asset.views.size())
      in.Fail("billboard ", i, ": view ", b.view, " out of range [0, ", asset.views.size(), ")");
    if (b.colour >= asset.colour_codebook_size)
      in.Fail("billboard ", i, ": colour index ", b.colour, " out of range [0, ", asset.colour_codebook_size, ")");
    if (b.alpha >= asset.alpha_codebook_size)
      in.Fail("billboard ", i, ": alpha index ", b.alpha, " out of range [0, ", asset.alpha_codebook_size, ")");
  }
}

VtreeAtlas ParseAtlas(const std::string& payload, const std::string& context, const VtreeAsset& asset) {
  ByteReader in(payload, context);
  VtreeAtlas atlas;
  atlas.width = in.Le<uint32_t>("atlas width");
  atlas.height = in.Le<uint32_t>("atlas height");
  atlas.tile_pitch = in.Le<uint32_t>("tile pitch");
  atlas.tiles_per_row = in.Le<uint32_t>("tiles per row");
  atlas.tile_count = in.Le<uint32_t>("tile count");
  if (atlas.width == 0 || atlas.height == 0 || atlas.width % 4 || atlas.height % 4 || atlas.width > kMaxAtlasSide ||
      atlas.height > kMaxAtlasSide)
    in.Fail("atlas size ", atlas.width, "x", atlas.height, " is not a multiple of 4 in [4, ", kMaxAtlasSide, "]");
  const uint32_t pitch = (uint32_t(asset.texels) + 3) / 4 * 4;
  if (atlas.tile_pitch != pitch) in.Fail("tile pitch ", atlas.tile_pitch, ", expected ", pitch);
  if (atlas.tiles_per_row == 0 || uint64_t(atlas.tiles_per_row) * pitch > atlas.width)
    in.Fail("tiles per row ", atlas.tiles_per_row, " do not fit the atlas width ", atlas.width);
  const uint32_t needed = std::max(asset.colour_codebook_size, asset.alpha_codebook_size);
  if (atlas.tile_count < needed) in.Fail("tile count ", atlas.tile_count, " is less than the codebook size ", needed);
  const uint64_t rows = (uint64_t(atlas.tile_count) + atlas.tiles_per_row - 1) / atlas.tiles_per_row;
  if (rows * pitch > atlas.height) in.Fail(atlas.tile_count, " tiles do not fit the atlas height ", atlas.height);
  const size_t bytes = size_t(atlas.width) * atlas.height;  // DXT5: 16 bytes per 16 texels
  if (in.remaining() != bytes) in.Fail("DXT5 data has ", in.remaining(), " bytes, expected ", bytes);
  const auto data = in.Take(bytes, "DXT5 data");
  atlas.dxt5.assign(data.begin(), data.end());
  return atlas;
}

}  // namespace

size_t VtreeAsset::BillboardCount() const {
  size_t count = 0;
  for (const auto& level : levels) count += level.billboards.size();
  return count;
}

size_t VtreeAsset::CellCount() const {
  size_t count = 0;
  for (const auto& level : levels) count += level.cells.size();
  return count;
}

std::string SerializeAsset(const VtreeAsset& asset, const VtreeWriteOptions& options) {
  if (asset.levels.empty() || asset.levels.size() > kMaxLevels)
    Fail("asset: ", asset.levels.size(), " levels, expected 1..", kMaxLevels);
  if (asset.views.size() > 65535) Fail("asset: ", asset.views.size(), " views exceed the limit of 65535");
  if (asset.atlas.dxt5.size() != size_t(asset.atlas.width) * asset.atlas.height)
    Fail("asset: atlas has ", asset.atlas.dxt5.size(), " bytes for ", asset.atlas.width, "x", asset.atlas.height);
  for (const auto& level : asset.levels)
    if (level.density.size() != level.cells.size()) Fail("asset: density and cell counts differ");
  ByteWriter file;
  file.Bytes(kMagic, sizeof(kMagic));
  file.Le<uint32_t>(kVtreeFormatVersion);
  AppendChunk(file, "HEAD", HeaderJson(asset), false, 0);
  for (uint32_t i = 0; i < asset.levels.size(); ++i) {
    AppendChunk(file, "CELL", CellPayload(asset.levels[i], i), options.zstd, options.zstd_level);
    AppendChunk(file, "BBRD", BillboardPayload(asset.levels[i], i), options.zstd, options.zstd_level);
  }
  AppendChunk(file, "ATLS", AtlasPayload(asset.atlas), options.zstd, options.zstd_level);
  return file.Take();
}

VtreeAsset ParseAsset(std::string_view bytes, const std::string& name, const VtreeReadOptions& options) {
  ByteReader file(bytes, name);
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    Fail(name, ": not a .vtree file (missing the VTREE magic)");
  file.Take(sizeof(kMagic), "magic");
  const uint32_t version = file.Le<uint32_t>("format version");
  if (version != kVtreeFormatVersion)
    Fail(name, ": format version ", version, " is not supported (this build reads version ", kVtreeFormatVersion, ")");

  auto next = [&](const char* expected) {
    if (file.remaining() == 0) Fail(name, ": truncated at byte ", file.offset(), ": expected chunk ", expected);
    Chunk chunk = ReadChunkHeader(file);
    if (chunk.tag != expected) Fail(ChunkContext(name, chunk), ": unexpected chunk, expected ", expected);
    return std::pair<Chunk, std::string>(chunk, Unpack(chunk, name, options));
  };

  VtreeAsset asset;
  uint32_t level_count = 0;
  {
    const auto [chunk, payload] = next("HEAD");
    ParseHeader(payload, ChunkContext(name, chunk), asset, level_count);
  }
  uint64_t resolution = 1;
  for (uint32_t i = 0; i < level_count; ++i) {
    {
      const auto [chunk, payload] = next("CELL");
      asset.levels.push_back(ParseCells(payload, ChunkContext(name, chunk), i, static_cast<uint32_t>(resolution)));
    }
    {
      const auto [chunk, payload] = next("BBRD");
      ParseBillboards(payload, ChunkContext(name, chunk), i, asset, asset.levels.back());
    }
    resolution *= asset.branching;
    if (resolution > 65536 && i + 1 < level_count)
      Fail(name, ": ", level_count, " levels of branching ", asset.branching, " exceed 16-bit cell coordinates");
  }
  {
    const auto [chunk, payload] = next("ATLS");
    asset.atlas = ParseAtlas(payload, ChunkContext(name, chunk), asset);
  }
  if (file.remaining() != 0)
    Fail(name, ": ", file.remaining(), " unexpected bytes after the last chunk at byte ", file.offset());
  return asset;
}

void WriteAsset(const std::filesystem::path& path, const VtreeAsset& asset, const VtreeWriteOptions& options) {
  CheckCanWrite(path, options.force);
  WriteFileAtomic(path, SerializeAsset(asset, options));
}

VtreeAsset ReadAsset(const std::filesystem::path& path, const VtreeReadOptions& options) {
  return ParseAsset(ReadFile(path), path.string(), options);
}

std::vector<VtreeChunkInfo> ListChunks(std::string_view bytes, const std::string& name) {
  ByteReader file(bytes, name);
  file.Take(sizeof(kMagic) + 4, "magic and version");
  std::vector<VtreeChunkInfo> chunks;
  while (file.remaining() > 0) {
    const Chunk chunk = ReadChunkHeader(file);
    chunks.push_back(
        {chunk.tag, chunk.offset, kChunkHeaderBytes + chunk.stored_size, chunk.raw_size, chunk.encoding == kZstd});
  }
  return chunks;
}

}  // namespace voltree
