#include "core/vtree.h"

#include <zstd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <tuple>
#include <unordered_set>

#include "core/bit_stream.h"
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
constexpr size_t kCellBytes = 3 * 2 + 4;  // explicit coordinates + density
constexpr uint8_t kExplicitCells = 0, kChildMasks = 1;
// Billboards of one level a reader accepts: 12 bytes each in memory, decoded from as little as one
// mask bit, so the chunk size limit alone would not bound the allocation.
constexpr uint32_t kMaxBillboardsPerLevel = uint32_t(1) << 25;
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
    // Small or incompressible payloads (the coarse levels, dense bit streams) stay raw.
    if (stored.size() >= raw.size()) stored = raw, encoding = kRaw;
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

// Bits a codeword index needs for a codebook of `size` entries (a codebook of 1 needs none).
int IndexBits(uint32_t size) { return size <= 1 ? 0 : std::bit_width(size - 1); }

// Bytes of the child mask a cell of the previous level carries: one bit per child (b^3 of them).
size_t ChildMaskBytes(int branching) { return (size_t(branching) * branching * branching + 7) / 8; }

// Child k of a parent: offset (k % b, k / b % b, k / b^2) from b x the parent's coordinates.
std::array<uint16_t, 3> ChildOf(const std::array<uint16_t, 3>& parent, uint32_t k, int b) {
  return {uint16_t(parent[0] * b + k % b), uint16_t(parent[1] * b + k / b % b), uint16_t(parent[2] * b + k / (b * b))};
}

bool ZyxLess(const std::array<uint16_t, 3>& a, const std::array<uint16_t, 3>& b) {
  return std::tie(a[2], a[1], a[0]) < std::tie(b[2], b[1], b[0]);
}

// The children of `parents` that `masks` name, sorted by (z, y, x): how kChildMasks cells decode.
std::vector<std::array<uint16_t, 3>> ChildrenFromMasks(const std::vector<std::array<uint16_t, 3>>& parents,
                                                       const std::vector<uint32_t>& masks, int branching) {
  std::vector<std::array<uint16_t, 3>> cells;
  for (size_t p = 0; p < parents.size(); ++p)
    for (uint32_t k = 0; k < uint32_t(branching * branching * branching); ++k)
      if ((masks[p] >> k) & 1u) cells.push_back(ChildOf(parents[p], k, branching));
  std::sort(cells.begin(), cells.end(), ZyxLess);
  return cells;
}

// Child masks of `parents` that give exactly `level.cells`, or nothing when the cells are not the
// (z, y, x)-sorted children of the previous level (then they are stored explicitly).
std::optional<std::vector<uint32_t>> ChildMasks(const VtreeLevel& level, const VtreeLevel* parent_level,
                                                int branching) {
  if (!parent_level) return std::nullopt;
  const auto& parents = parent_level->cells;
  // (coordinates, stored position), sorted: the first parent with given coordinates is found by bisection.
  std::vector<std::pair<std::array<uint16_t, 3>, size_t>> sorted_parents;
  for (size_t p = 0; p < parents.size(); ++p) sorted_parents.push_back({parents[p], p});
  std::stable_sort(sorted_parents.begin(), sorted_parents.end(),
                   [](const auto& a, const auto& b) { return ZyxLess(a.first, b.first); });
  std::vector<uint32_t> masks(parents.size(), 0);
  for (const auto& cell : level.cells) {
    const std::array<uint16_t, 3> parent = {uint16_t(cell[0] / branching), uint16_t(cell[1] / branching),
                                            uint16_t(cell[2] / branching)};
    const auto it = std::lower_bound(sorted_parents.begin(), sorted_parents.end(), parent,
                                     [](const auto& a, const auto& key) { return ZyxLess(a.first, key); });
    if (it == sorted_parents.end() || it->first != parent) return std::nullopt;
    const uint32_t k =
        uint32_t(cell[0] % branching + branching * (cell[1] % branching + branching * (cell[2] % branching)));
    masks[it->second] |= 1u << k;
  }
  if (ChildrenFromMasks(parents, masks, branching) != level.cells) return std::nullopt;
  return masks;
}

// Density as 4 byte planes (every first byte, then every second, ...): the exponent bytes of
// neighbouring cells repeat, which zstd then finds.
void AppendDensityPlanes(ByteWriter& out, const std::vector<float>& density) {
  std::string planes(density.size() * 4, '\0');
  for (size_t i = 0; i < density.size(); ++i) {
    const uint32_t bits = std::bit_cast<uint32_t>(density[i]);
    for (size_t k = 0; k < 4; ++k) planes[k * density.size() + i] = char((bits >> (8 * k)) & 0xFF);
  }
  out.Bytes(planes);
}

std::string CellPayload(const VtreeLevel& level, const VtreeLevel* parent_level, uint32_t index, int branching) {
  ByteWriter out;
  out.Le<uint32_t>(index);
  out.Le<uint32_t>(level.resolution);
  out.Le<uint32_t>(static_cast<uint32_t>(level.cells.size()));
  const auto masks = ChildMasks(level, parent_level, branching);
  out.Le<uint8_t>(masks ? kChildMasks : kExplicitCells);
  if (masks) {
    for (uint32_t mask : *masks)
      for (size_t k = 0; k < ChildMaskBytes(branching); ++k) out.Le<uint8_t>(uint8_t((mask >> (8 * k)) & 0xFF));
  } else {
    for (const auto& cell : level.cells)
      for (uint16_t c : cell) out.Le(c);
  }
  AppendDensityPlanes(out, level.density);
  return out.Take();
}

// An index stream: up to 8 bits bit-packed; wider, the low bytes first (byte-aligned, so zstd
// models them), then the high bits bit-packed.
void AppendIndices(ByteWriter& out, const std::vector<uint32_t>& indices, int bits) {
  const int low = bits > 8 ? 8 : 0;
  if (low)
    for (uint32_t index : indices) out.Le<uint8_t>(uint8_t(index & 0xFF));
  BitWriter high;
  for (uint32_t index : indices) high.Put(index >> low, bits - low);
  out.Bytes(high.Take());
}

uint64_t IndexStreamBytes(uint64_t count, int bits) {
  return bits > 8 ? count + BitStreamBytes(count, bits - 8) : BitStreamBytes(count, bits);
}

std::string BillboardPayload(const VtreeAsset& asset, const VtreeLevel& level, uint32_t index) {
  const size_t views = asset.views.size();
  for (size_t i = 0; i < level.billboards.size(); ++i) {
    const auto& b = level.billboards[i];
    if (b.cell >= level.cells.size() || b.view >= views)
      Fail("asset: level ", index, " billboard ", i, " names cell ", b.cell, " and view ", b.view, " beyond the ",
           level.cells.size(), " cells and ", views, " views");
    if (i > 0 && std::tie(level.billboards[i - 1].cell, level.billboards[i - 1].view) >= std::tie(b.cell, b.view))
      Fail("asset: level ", index, " billboard ", i, " is out of (cell, view) order or repeats one");
    if (b.colour >= asset.colour_codebook_size || b.alpha >= asset.alpha_codebook_size)
      Fail("asset: level ", index, " billboard ", i, " names codewords (", b.colour, ", ", b.alpha,
           ") beyond the codebooks of ", asset.colour_codebook_size, " and ", asset.alpha_codebook_size);
  }
  ByteWriter out;
  out.Le<uint32_t>(index);
  out.Le<uint64_t>(level.billboards_before_pruning);
  out.Le<uint32_t>(static_cast<uint32_t>(level.billboards.size()));
  const int colour_bits = IndexBits(asset.colour_codebook_size), alpha_bits = IndexBits(asset.alpha_codebook_size);
  out.Le<uint8_t>(uint8_t(colour_bits));
  out.Le<uint8_t>(uint8_t(alpha_bits));
  BitWriter masks;
  size_t next = 0;
  for (uint32_t cell = 0; cell < level.cells.size(); ++cell)
    for (size_t view = 0; view < views; ++view) {
      const bool present =
          next < level.billboards.size() && level.billboards[next].cell == cell && level.billboards[next].view == view;
      masks.Put(present ? 1 : 0, 1);
      next += present;
    }
  out.Bytes(masks.Take());
  std::vector<uint32_t> colours, alphas;
  for (const auto& b : level.billboards) colours.push_back(b.colour), alphas.push_back(b.alpha);
  AppendIndices(out, colours, colour_bits);
  AppendIndices(out, alphas, alpha_bits);
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
                      uint32_t expected_resolution, const VtreeLevel* parent_level, int branching) {
  ByteReader in(payload, context);
  VtreeLevel level;
  if (const auto stored = in.Le<uint32_t>("level index"); stored != index)
    in.Fail("level index ", stored, ", expected ", index);
  level.resolution = in.Le<uint32_t>("resolution");
  if (level.resolution != expected_resolution)
    in.Fail("resolution ", level.resolution, ", expected ", expected_resolution, " (branching^level)");
  const uint32_t count = in.Le<uint32_t>("cell count");
  const uint64_t total_cells = uint64_t(level.resolution) * level.resolution * level.resolution;
  if (count > total_cells) in.Fail("cell count ", count, " exceeds ", total_cells, " cells of the grid");
  const uint8_t coding = in.Le<uint8_t>("cell coding");
  if (coding == kExplicitCells) {
    if (in.remaining() != uint64_t(count) * kCellBytes)
      in.Fail("cell count ", count, " needs ", uint64_t(count) * kCellBytes, " bytes, the chunk has ", in.remaining());
    level.cells.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
      for (auto& c : level.cells[i]) {
        c = in.Le<uint16_t>("cell coordinate");
        if (c >= level.resolution) in.Fail("cell ", i, " coordinate ", c, " out of range [0, ", level.resolution, ")");
      }
    }
  } else if (coding == kChildMasks) {
    if (!parent_level) in.Fail("cells coded as child masks, but level 0 has no parent level");
    const size_t mask_bytes = ChildMaskBytes(branching), parents = parent_level->cells.size();
    if (in.remaining() != uint64_t(parents) * mask_bytes + uint64_t(count) * 4)
      in.Fail("child masks of ", parents, " parent cells and ", count, " densities need ",
              uint64_t(parents) * mask_bytes + uint64_t(count) * 4, " bytes, the chunk has ", in.remaining());
    const uint32_t children = uint32_t(branching * branching * branching);
    std::vector<uint32_t> masks(parents, 0);
    uint64_t set = 0;
    for (size_t p = 0; p < parents; ++p) {
      for (size_t k = 0; k < mask_bytes; ++k) masks[p] |= uint32_t(in.Le<uint8_t>("child mask")) << (8 * k);
      if (children < 32 && (masks[p] >> children) != 0)
        in.Fail("parent cell ", p, ": child mask names children beyond the ", children, " of a cell");
      set += std::popcount(masks[p]);
    }
    if (set != count) in.Fail("child masks name ", set, " cells, the cell count is ", count);
    level.cells = ChildrenFromMasks(parent_level->cells, masks, branching);
  } else {
    in.Fail("unknown cell coding ", int(coding), " (expected 0 explicit or 1 child masks)");
  }
  if (in.remaining() != uint64_t(count) * 4)
    in.Fail("densities need ", uint64_t(count) * 4, " bytes, the chunk has ", in.remaining());
  const std::string_view planes = in.Take(size_t(count) * 4, "density");
  level.density.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t bits = 0;
    for (size_t k = 0; k < 4; ++k) bits |= uint32_t(uint8_t(planes[k * count + i])) << (8 * k);
    level.density[i] = std::bit_cast<float>(bits);
    if (!(level.density[i] >= 0) || !std::isfinite(level.density[i]))
      in.Fail("cell ", i, " density ", level.density[i], " is not finite and >= 0");
  }
  return level;
}

// Reads an index stream (AppendIndices) of `count` indices, each below `size`.
std::vector<uint16_t> ReadIndices(ByteReader& in, uint32_t count, int bits, uint32_t size, const char* what) {
  const int low = bits > 8 ? 8 : 0;
  const std::string_view low_bytes = in.Take(low ? count : 0, what);
  BitReader high(in.Take(BitStreamBytes(count, bits - low), what));
  std::vector<uint16_t> indices(count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t index = (low ? uint8_t(low_bytes[i]) : 0u) | (high.Get(bits - low) << low);
    if (index >= size) in.Fail("billboard ", i, ": ", what, " ", index, " out of range [0, ", size, ")");
    indices[i] = uint16_t(index);
  }
  return indices;
}

void ParseBillboards(const std::string& payload, const std::string& context, uint32_t index, const VtreeAsset& asset,
                     VtreeLevel& level) {
  ByteReader in(payload, context);
  if (const auto stored = in.Le<uint32_t>("level index"); stored != index)
    in.Fail("level index ", stored, ", expected ", index);
  level.billboards_before_pruning = in.Le<uint64_t>("billboards before pruning");
  const uint32_t count = in.Le<uint32_t>("billboard count");
  const int colour_bits = in.Le<uint8_t>("colour index bits"), alpha_bits = in.Le<uint8_t>("alpha index bits");
  if (colour_bits != IndexBits(asset.colour_codebook_size))
    in.Fail("colour indices of ", colour_bits, " bits, expected ", IndexBits(asset.colour_codebook_size), " for ",
            asset.colour_codebook_size, " codewords");
  if (alpha_bits != IndexBits(asset.alpha_codebook_size))
    in.Fail("alpha indices of ", alpha_bits, " bits, expected ", IndexBits(asset.alpha_codebook_size), " for ",
            asset.alpha_codebook_size, " codewords");
  if (count > kMaxBillboardsPerLevel)
    in.Fail("billboard count ", count, " exceeds the limit of ", kMaxBillboardsPerLevel, " per level");
  const uint64_t views = asset.views.size(), mask_bits = uint64_t(level.cells.size()) * views;
  const uint64_t needed =
      BitStreamBytes(mask_bits, 1) + IndexStreamBytes(count, colour_bits) + IndexStreamBytes(count, alpha_bits);
  if (in.remaining() != needed)
    in.Fail("billboard count ", count, " with ", level.cells.size(), " cells of ", views, " views needs ", needed,
            " bytes, the chunk has ", in.remaining());
  const std::string_view masks = in.Take(BitStreamBytes(mask_bits, 1), "view masks");
  uint64_t present = 0;
  for (size_t i = 0; i < masks.size(); ++i) {
    const uint8_t byte = uint8_t(masks[i]);
    if (i + 1 == masks.size() && mask_bits % 8 && (byte >> (mask_bits % 8)) != 0)
      in.Fail("view masks have bits set beyond the ", mask_bits, " of ", level.cells.size(), " cells");
    present += std::popcount(byte);
  }
  if (present != count) in.Fail("view masks name ", present, " billboards, the billboard count is ", count);
  level.billboards.resize(count);
  size_t next = 0;
  for (size_t i = 0; i < masks.size(); ++i)
    for (uint8_t byte = uint8_t(masks[i]); byte != 0; byte &= uint8_t(byte - 1)) {
      const uint64_t bit = i * 8 + size_t(std::countr_zero(byte));
      level.billboards[next].cell = uint32_t(bit / views);
      level.billboards[next].view = uint16_t(bit % views);
      ++next;
    }
  const auto colours = ReadIndices(in, count, colour_bits, asset.colour_codebook_size, "colour index");
  const auto alphas = ReadIndices(in, count, alpha_bits, asset.alpha_codebook_size, "alpha index");
  for (uint32_t i = 0; i < count; ++i) level.billboards[i].colour = colours[i], level.billboards[i].alpha = alphas[i];
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

size_t VtreeAsset::LeafCellCount() const {
  const auto key = [](uint32_t i, uint32_t j, uint32_t k) {
    return uint64_t(i) | uint64_t(j) << 21 | uint64_t(k) << 42;
  };
  size_t leaves = levels.empty() ? 0 : levels.back().cells.size();
  const uint32_t b = uint32_t(std::max(branching, 1));
  for (size_t l = 0; l + 1 < levels.size(); ++l) {
    std::unordered_set<uint64_t> parents;  // lookups only
    for (const auto& c : levels[l + 1].cells) parents.insert(key(c[0] / b, c[1] / b, c[2] / b));
    for (const auto& c : levels[l].cells) leaves += !parents.count(key(c[0], c[1], c[2]));
  }
  return leaves;
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
  // The atlas first, then the levels coarse to fine: any prefix that ends after a level's BBRD
  // draws that level and the coarser ones.
  AppendChunk(file, "ATLS", AtlasPayload(asset.atlas), options.zstd, options.zstd_level);
  for (uint32_t i = 0; i < asset.levels.size(); ++i) {
    const VtreeLevel* parent = i > 0 ? &asset.levels[i - 1] : nullptr;
    AppendChunk(file, "CELL", CellPayload(asset.levels[i], parent, i, asset.branching), options.zstd,
                options.zstd_level);
    AppendChunk(file, "BBRD", BillboardPayload(asset, asset.levels[i], i), options.zstd, options.zstd_level);
  }
  return file.Take();
}

void VtreeReadOptions::Check() const {
  if (max_level < -1 || max_level >= int(kMaxLevels))
    FailOption("VtreeReadOptions.max_level", "must be an octree level in [0, ", kMaxLevels - 1, "] (or -1: all), got ",
               max_level);
}

VtreeAsset ParseAsset(std::string_view bytes, const std::string& name, const VtreeReadOptions& options) {
  options.Check();
  ByteReader file(bytes, name);
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    Fail(name, ": not a .vtree file (missing the VTREE magic)");
  file.Take(sizeof(kMagic), "magic");
  const uint32_t version = file.Le<uint32_t>("format version");
  if (version != kVtreeFormatVersion)
    Fail(name, ": format version ", version, " is not supported (this build reads version ", kVtreeFormatVersion,
         "); the asset must be rebuilt with this voltree (voltree compress WORKSPACE --force)");

  auto next = [&](const char* expected) {
    if (file.remaining() == 0) Fail(name, ": truncated at byte ", file.offset(), ": expected chunk ", expected);
    Chunk chunk = ReadChunkHeader(file);
    if (chunk.tag != expected) Fail(ChunkContext(name, chunk), ": unexpected chunk, expected ", expected);
    return std::pair<Chunk, std::string>(chunk, Unpack(chunk, name, options));
  };
  // Why the chunk that starts at byte `at` is not wholly in `bytes`, or "" when it is; `end` is
  // set to where a whole chunk ends.
  auto missing_chunk = [&](size_t at, const char* tag, uint32_t level, size_t* end) -> std::string {
    const size_t left = bytes.size() - at;
    if (left == 0) return Str("the file ends at byte ", at, ", before the ", tag, " chunk of level ", level);
    if (left < kChunkHeaderBytes)
      return Str("the file ends at byte ", bytes.size(), ", inside the header of the ", tag, " chunk of level ", level,
                 " at byte ", at);
    const uint64_t stored = ByteReader(bytes.substr(at + 8, 8), name).Le<uint64_t>("chunk size");
    if (stored > left - kChunkHeaderBytes)
      return Str("the file ends at byte ", bytes.size(), ", inside the ", tag, " chunk of level ", level,
                 " that starts at byte ", at, " and needs ", kChunkHeaderBytes + stored, " bytes");
    *end = at + kChunkHeaderBytes + size_t(stored);
    return "";
  };

  VtreeAsset asset;
  uint32_t level_count = 0;
  {
    const auto [chunk, payload] = next("HEAD");
    ParseHeader(payload, ChunkContext(name, chunk), asset, level_count);
  }
  {
    const auto [chunk, payload] = next("ATLS");
    asset.atlas = ParseAtlas(payload, ChunkContext(name, chunk), asset);
  }
  VtreeLoadReport report;
  report.levels_in_file = level_count;
  report.file_bytes = bytes.size();
  const uint32_t wanted = options.max_level < 0 ? level_count : std::min(level_count, uint32_t(options.max_level) + 1);
  uint64_t resolution = 1;
  for (uint32_t i = 0; i < wanted; ++i) {
    if (options.allow_partial && i > 0) {
      size_t cell_end = 0, billboards_end = 0;
      std::string why = missing_chunk(file.offset(), "CELL", i, &cell_end);
      if (why.empty()) why = missing_chunk(cell_end, "BBRD", i, &billboards_end);
      if (!why.empty()) {
        report.truncated = true;
        report.missing = Str("levels ", i, "..", level_count - 1, " of 0..", level_count - 1, " are missing: ", why);
        break;
      }
    }
    {
      const auto [chunk, payload] = next("CELL");
      const VtreeLevel* parent = i > 0 ? &asset.levels[i - 1] : nullptr;
      asset.levels.push_back(ParseCells(payload, ChunkContext(name, chunk), i, static_cast<uint32_t>(resolution),
                                        parent, asset.branching));
    }
    {
      const auto [chunk, payload] = next("BBRD");
      ParseBillboards(payload, ChunkContext(name, chunk), i, asset, asset.levels.back());
    }
    resolution *= asset.branching;
    if (resolution > 65536 && i + 1 < level_count)
      Fail(name, ": ", level_count, " levels of branching ", asset.branching, " exceed 16-bit cell coordinates");
  }
  report.levels_loaded = uint32_t(asset.levels.size());
  if (wanted == level_count && !report.truncated && file.remaining() != 0)
    Fail(name, ": ", file.remaining(), " unexpected bytes after the last chunk at byte ", file.offset());
  if (options.report) *options.report = report;
  return asset;
}

void WriteAsset(const std::filesystem::path& path, const VtreeAsset& asset, const VtreeWriteOptions& options) {
  CheckCanWrite(path, options.force);
  WriteFileAtomic(path, SerializeAsset(asset, options));
}

VtreeAsset ReadAsset(const std::filesystem::path& path, const VtreeReadOptions& options) {
  return ParseAsset(ReadFile(path), path.string(), options);
}

std::vector<VtreeChunkInfo> ListChunks(std::string_view bytes, const std::string& name, bool allow_partial) {
  ByteReader file(bytes, name);
  file.Take(sizeof(kMagic) + 4, "magic and version");
  std::vector<VtreeChunkInfo> chunks;
  while (file.remaining() > 0) {
    if (allow_partial) {
      // A chunk cut off by the end of the file: listed as incomplete, and the last.
      VtreeChunkInfo cut;
      cut.offset = file.offset();
      cut.complete = false;
      if (file.remaining() < kChunkHeaderBytes) {
        cut.tag = TagText(bytes.substr(file.offset(), std::min<size_t>(4, file.remaining())));
        chunks.push_back(cut);
        break;
      }
      ByteReader peek(bytes.substr(file.offset()), name);
      cut.tag = TagText(peek.Take(4, "chunk tag"));
      cut.zstd = peek.Le<uint32_t>("chunk encoding") == kZstd;
      const uint64_t stored = peek.Le<uint64_t>("chunk size");
      cut.raw_bytes = peek.Le<uint64_t>("chunk raw size");
      if (stored > file.remaining() - kChunkHeaderBytes) {
        cut.stored_bytes = kChunkHeaderBytes + stored, cut.payload_bytes = stored;
        chunks.push_back(cut);
        break;
      }
    }
    const Chunk chunk = ReadChunkHeader(file);
    chunks.push_back({chunk.tag, chunk.offset, kChunkHeaderBytes + chunk.stored_size, chunk.stored_size, chunk.raw_size,
                      chunk.encoding == kZstd});
  }
  return chunks;
}

}  // namespace voltree
