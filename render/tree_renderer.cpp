#include "render/tree_renderer.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "render/alpha_extent.h"
#include "render/frame_record.h"
#include "render/gl.h"
#include "render/gl_context.h"
#include "render/offscreen_render.h"

namespace voltree {
namespace {

// The vertex shader is kVertexHeader + the level count + kProjectionGlsl + kVertexMain.
constexpr const char* kVertexHeader = R"(#version 430 core
layout(std430, binding = 0) readonly buffer Frame { uvec4 frame[]; };          // FrameRecord, one per cell drawn
layout(std430, binding = 1) readonly buffer AlphaExtents { uint extents[]; };  // per tile (AlphaExtent::Packed)
)";

constexpr const char* kVertexMain = R"(
uniform vec3 uCameraRight, uCameraUp;  // world directions of image +X and -Y
uniform vec3 uCameraForward, uEye;     // image +Z (world), the camera centre
uniform int uTexels;                   // billboard side n
uniform int uTrimQuads;                // quads bound the alpha extents (TreeRenderOptions::trim_quads)
uniform vec3 uRight[2], uUp[2];        // the two input views' billboard axes (world)
uniform float uScale;                  // billboard side / cell edge
uniform mat3 uModelRotation;           // the instance: world = T + s * R * asset
uniform vec3 uModelTranslation;
uniform float uModelScale;
uniform vec3 uOrigin;                  // the root cube's corner (asset frame)
uniform float uCellSize[kMaxRenderedLevels];  // cell edge per level (asset frame)
out vec3 vWorld;
flat out vec4 vCell;    // world centre, world side
flat out uvec3 vTiles;  // tiles of A, tiles of B, presence mask
flat out int vLevel;

// Half extents on the camera axes that hold both input views' whole squares (5% for perspective).
vec4 SquareBounds(float side) {
  vec2 half_extent = vec2(0.0);
  for (int k = 0; k < 2; ++k) {
    half_extent = max(half_extent, vec2(abs(dot(uRight[k], uCameraRight)) + abs(dot(uUp[k], uCameraRight)),
                                        abs(dot(uRight[k], uCameraUp)) + abs(dot(uUp[k], uCameraUp))));
  }
  half_extent *= 0.5 * side * 1.05;
  return vec4(-half_extent, half_extent);
}

// The bounds, on the quad's plane (through the centre, facing the camera), of what the eye sees of
// each present view's square where its alpha can be non-zero: the trimmed rectangles' corners
// projected from the eye, which is exactly where the fragment shader's rays meet them. The
// whole squares' bounds when a corner lies behind the eye's plane.
vec4 TrimmedBounds(vec3 centre, float side, uvec3 tiles) {
  float centre_depth = dot(centre - uEye, uCameraForward);
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  for (int k = 0; k < 2; ++k) {
    if ((tiles.z & (1u << k)) == 0u) continue;
    uint e = extents[(k == 0 ? tiles.x : tiles.y) >> 16];
    vec4 st = vec4(e & 0xffu, (e >> 8) & 0xffu, (e >> 16) & 0xffu, e >> 24) / (2.0 * float(uTexels));
    for (int c = 0; c < 4; ++c) {
      vec2 corner = vec2((c & 1) != 0 ? st.z : st.x, (c & 2) != 0 ? st.w : st.y);
      vec3 p = centre + side * ((corner.x - 0.5) * uRight[k] + (0.5 - corner.y) * uUp[k]);
      float depth = dot(p - uEye, uCameraForward);
      if (depth <= 1e-3 * centre_depth) return SquareBounds(side);
      vec3 q = uEye + (p - uEye) * (centre_depth / depth) - centre;
      vec2 xy = vec2(dot(q, uCameraRight), dot(q, uCameraUp));
      lo = min(lo, xy), hi = max(hi, xy);
    }
  }
  float margin = 1e-3 * side;  // float rounding; the filter already reaches zero at the extent
  return vec4(lo - margin, hi + margin);
}

void main() {
  uvec4 record = frame[gl_InstanceID];
  int level = int(record.w & 0xffu);
  vec3 cell = vec3(record.x & 0x3ffu, (record.x >> 10) & 0x3ffu, record.x >> 20);
  float edge = uCellSize[level];
  vec3 centre = uModelTranslation + uModelScale * (uModelRotation * (uOrigin + edge * (cell + 0.5)));
  float side = uScale * edge * uModelScale;
  vTiles = uvec3(record.y, record.z, record.w >> 8);
  vec4 bounds = uTrimQuads != 0 && dot(centre - uEye, uCameraForward) > 0.0 ? TrimmedBounds(centre, side, vTiles)
                                                                             : SquareBounds(side);
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  vec2 xy = mix(bounds.xy, bounds.zw, corner);
  vWorld = centre + xy.x * uCameraRight + xy.y * uCameraUp;
  vCell = vec4(centre, side);
  vLevel = level;
  gl_Position = ProjectToClip(vWorld);
}
)";

constexpr const char* kFragmentShader = R"(#version 430 core
uniform sampler2D uAtlas;
uniform vec3 uEye;
uniform vec3 uDirection[2], uRight[2], uUp[2];  // the two input views' billboard frames
uniform float uWeight[2];
uniform int uTexels, uPitch, uTilesPerRow;
uniform vec2 uAtlasSize;
uniform int uTintLevels;
in vec3 vWorld;
flat in vec4 vCell;
flat in uvec3 vTiles;
flat in int vLevel;
out vec4 color;

// Distinct hues per level for LOD figures (level 0 red ... level 7 magenta).
const vec3 kLevelColours[8] = vec3[8](vec3(0.9, 0.1, 0.1), vec3(0.95, 0.55, 0.1), vec3(0.95, 0.9, 0.1),
                                      vec3(0.2, 0.8, 0.2), vec3(0.1, 0.8, 0.8), vec3(0.15, 0.35, 0.95),
                                      vec3(0.6, 0.25, 0.9), vec3(0.95, 0.3, 0.8));

vec2 TileTexel(uint tile, vec2 texel) {
  vec2 origin = vec2(float(int(tile) % uTilesPerRow), float(int(tile) / uTilesPerRow)) * float(uPitch);
  // Clamped half a texel inside the n x n tile: bilinear filtering never reads a neighbour.
  return (origin + clamp(texel, vec2(0.5), vec2(float(uTexels) - 0.5))) / uAtlasSize;
}

// Premultiplied RGBA of input view k's billboard where the pixel's ray meets its plane.
vec4 Fetch(int k, uint tiles) {
  vec3 ray = vWorld - uEye;
  float denominator = dot(ray, uDirection[k]);
  if (abs(denominator) < 1e-12) return vec4(0.0);
  vec3 local = uEye + ray * (dot(vCell.xyz - uEye, uDirection[k]) / denominator) - vCell.xyz;
  vec2 st = vec2(dot(local, uRight[k]), -dot(local, uUp[k])) / vCell.w + 0.5;  // texel (0,0) top-left
  if (any(lessThan(st, vec2(0.0))) || any(greaterThan(st, vec2(1.0)))) return vec4(0.0);
  vec2 texel = st * float(uTexels);
  vec3 rgb = texture(uAtlas, TileTexel(tiles & 0xffffu, texel)).rgb;
  float a = texture(uAtlas, TileTexel(tiles >> 16, texel)).a;
  return vec4(rgb * a, a);
}

void main() {
  vec4 sum = vec4(0.0);
  if ((vTiles.z & 1u) != 0u) sum += uWeight[0] * Fetch(0, vTiles.x);
  if ((vTiles.z & 2u) != 0u) sum += uWeight[1] * Fetch(1, vTiles.y);
  if (sum.a <= 0.0) discard;
  if (uTintLevels != 0) sum.rgb = sum.a * mix(sum.rgb / sum.a, kLevelColours[clamp(vLevel, 0, 7)], 0.7);
  color = sum;
}
)";

using Clock = std::chrono::steady_clock;
double Ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

// The billboard frame of an input view as the reconstruction built it: right = dir x up.
struct BillboardFrame {
  Eigen::Vector3f direction, right, up;
};
BillboardFrame FrameOf(const VtreeView& view) {
  const Eigen::Vector3d d = view.direction.normalized();
  const Eigen::Vector3d up = view.up.normalized();
  return {d.cast<float>(), d.cross(up).normalized().cast<float>(), up.cast<float>()};
}

void SetVec3Array(const ShaderProgram& program, const char* name, const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const float values[6] = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()};
  glProgramUniform3fv(program.id(), program.Location(name), 2, values);
}

}  // namespace

void TreeRenderOptions::Check() const {
  lod.Check();
  for (float c : background)
    if (!(c >= 0 && c <= 1)) FailOption("TreeRenderOptions.background", "components must be in [0, 1]");
  if (!(billboard_scale > 0)) FailOption("TreeRenderOptions.billboard_scale", "must be > 0, got ", billboard_scale);
}

TreeRenderer::TreeRenderer(const VtreeAsset& asset) : views_(asset.views), texels_(asset.texels), index_(asset) {
  if (asset.levels.empty()) Fail("render: the asset has no levels");
  if (views_.empty()) Fail("render: the asset has no input views");
  root_size_ = asset.size;
  centre_ = asset.origin + Eigen::Vector3d::Constant(0.5 * asset.size);
  program_ = ShaderProgram::Graphics("vtree billboards",
                                     std::string(kVertexHeader) +
                                         Str("const int kMaxRenderedLevels = ", kMaxRenderedLevels, ";\n") +
                                         kProjectionGlsl + kVertexMain,
                                     kFragmentShader);

  cell_codes_ = PackCellCoordinates(asset);
  records_ = GlStreamBuffer(asset.LeafCellCount() * sizeof(FrameRecord));
  for (uint32_t b = 0; b < index_.BillboardCount(); ++b) {
    const VtreeBillboard& record = index_.Billboard(b);
    if (record.colour >= asset.atlas.tile_count || record.alpha >= asset.atlas.tile_count)
      Fail("render: billboard ", b, " names a tile beyond the atlas's ", asset.atlas.tile_count);
  }

  const VtreeAtlas& atlas = asset.atlas;
  if (atlas.width == 0 || atlas.height == 0 || atlas.width % 4 || atlas.height % 4 ||
      atlas.dxt5.size() != size_t(atlas.width) * atlas.height)
    Fail("render: bad atlas ", atlas.width, "x", atlas.height, " with ", atlas.dxt5.size(), " bytes");
  atlas_ = GlTexture::Dxt5(int(atlas.width), int(atlas.height), atlas.dxt5,
                           "render: uploading the DXT5 atlas (needs GL_EXT_texture_compression_s3tc)");
  atlas_bytes_ = atlas.dxt5.size();
  const std::vector<AlphaExtent> extents = AlphaTileExtents(atlas, asset.texels);
  std::vector<uint32_t> packed_extents(extents.size());
  empty_alpha_tiles_.resize(extents.size());
  for (size_t tile = 0; tile < extents.size(); ++tile)
    packed_extents[tile] = extents[tile].Packed(), empty_alpha_tiles_[tile] = extents[tile].Empty();
  alpha_extents_ = GlBuffer(packed_extents.data(), packed_extents.size() * sizeof(uint32_t), 16);

  program_.Set("uAtlas", 0);
  program_.Set("uTexels", asset.texels);
  program_.Set("uPitch", int(atlas.tile_pitch));
  program_.Set("uTilesPerRow", int(atlas.tiles_per_row));
  program_.Set("uAtlasSize", Eigen::Vector2f(float(atlas.width), float(atlas.height)));
  program_.Set("uOrigin", Eigen::Vector3f(asset.origin.cast<float>()));
  std::vector<float> cell_sizes(kMaxRenderedLevels, 0.0f);
  for (int level = 0; level < index_.levels(); ++level) cell_sizes[level] = float(index_.CellSize(level));
  glProgramUniform1fv(program_.id(), program_.Location("uCellSize"), kMaxRenderedLevels, cell_sizes.data());
}

double TreeRenderer::BoundingRadius(double billboard_scale) const {
  // Cells lie in the root cube (half diagonal sqrt(3)/2); a billboard square of side s * edge
  // reaches sqrt(2)/2 * s * edge from its centre; the bound is linear in the edge (<= root), so the
  // worst case is the root's billboard or a tiny cell at a corner.
  return root_size_ * std::max(0.5 * std::sqrt(3.0), 0.5 * std::sqrt(2.0) * billboard_scale);
}

GpuMemory TreeRenderer::GpuBytes() const { return {alpha_extents_.bytes() + records_.capacity(), atlas_bytes_}; }

FrameStats TreeRenderer::Plan(const View& camera, const TreeRenderOptions& options, std::vector<FrameRecord>* records,
                              std::vector<uint8_t>* lod_state, const InstanceTransform& model) const {
  FrameStats stats;
  // The asset's frame: view selection, traversal order and LOD are all computed there.
  const Eigen::Vector3d eye = model.ToAsset(camera.pose.Center());
  stats.views = SelectViews(views_, centre_, eye);
  if (options.nearest_view_only)
    stats.views.second = stats.views.first, stats.views.first_weight = 1, stats.views.second_weight = 0;
  const TraversalCamera traversal_camera{eye, 0.5 * (camera.camera.FocalX() + camera.camera.FocalY()),
                                         model.DirectionToAsset(camera.pose.ViewDirection())};
  std::vector<uint32_t> cells;
  TraverseBackToFront(index_, traversal_camera, options.lod, texels_, &cells, lod_state);
  records->clear();
  const bool two = stats.views.second != stats.views.first && stats.views.second_weight > 0;
  // A billboard whose alpha tile is 0 everywhere draws nothing (when trimming; else it is drawn
  // to show what that costs).
  const auto drawn = [&](uint32_t billboard) {
    return billboard != OctreeIndex::kNone &&
                   !(options.trim_quads && empty_alpha_tiles_[index_.Billboard(billboard).alpha])
               ? billboard
               : OctreeIndex::kNone;
  };
  const auto billboard = [&](uint32_t index) {
    return index != OctreeIndex::kNone ? &index_.Billboard(index) : nullptr;
  };
  for (uint32_t cell : cells) {
    const uint32_t a = drawn(index_.FindBillboard(cell, uint16_t(stats.views.first)));
    const uint32_t b = two ? drawn(index_.FindBillboard(cell, uint16_t(stats.views.second))) : OctreeIndex::kNone;
    if (a == OctreeIndex::kNone && b == OctreeIndex::kNone) continue;  // pruned or empty in both views
    records->push_back(MakeFrameRecord(cell_codes_[cell], index_.LevelOf(cell), billboard(a), billboard(b)));
    stats.billboards += (a != OctreeIndex::kNone) + (b != OctreeIndex::kNone);
    const int level = index_.LevelOf(cell);
    if (stats.cells_per_level.size() <= size_t(level)) stats.cells_per_level.resize(level + 1, 0);
    ++stats.cells_per_level[level];
    stats.min_level = stats.min_level < 0 ? level : std::min(stats.min_level, level);
    stats.max_level = std::max(stats.max_level, level);
  }
  stats.cells = records->size();
  return stats;
}

FrameStats TreeRenderer::Draw(const View& camera, const TreeRenderOptions& options, const TreeDraw& draw) {
  options.Check();
  camera.camera.Check();
  draw.model.Check();
  const auto start = Clock::now();
  std::vector<FrameRecord> records;
  std::vector<uint8_t>* lod_state = draw.lod_state ? draw.lod_state : options.lod_history ? &lod_state_ : nullptr;
  FrameStats stats = Plan(camera, options, &records, lod_state, draw.model);
  stats.traversal_ms = Ms(start, Clock::now());

  if (!records.empty()) {
    records_.Upload(records.data(), records.size() * sizeof(records[0]));

    const Eigen::Vector3d eye = camera.pose.Center();
    const Eigen::Vector3d world_centre = draw.model.ToWorld(centre_);
    const DepthRange depth =
        draw.depth ? *draw.depth
                   : DepthRangeForSphere(eye, world_centre, draw.model.scale * BoundingRadius(options.billboard_scale));
    SetProjectionUniforms(program_, camera, depth);
    const Eigen::Matrix3d rotation = camera.pose.rotation.toRotationMatrix();
    program_.Set("uCameraRight", Eigen::Vector3f(rotation.row(0).transpose().cast<float>()));
    program_.Set("uCameraUp", Eigen::Vector3f((-rotation.row(1)).transpose().cast<float>()));
    program_.Set("uCameraForward", Eigen::Vector3f(rotation.row(2).transpose().cast<float>()));
    program_.Set("uTrimQuads", options.trim_quads ? 1 : 0);
    program_.Set("uEye", Eigen::Vector3f(eye.cast<float>()));
    program_.Set("uScale", float(options.billboard_scale));
    program_.Set("uModelRotation", Eigen::Matrix3f(draw.model.Rotation().cast<float>()));
    program_.Set("uModelTranslation", Eigen::Vector3f(draw.model.translation.cast<float>()));
    program_.Set("uModelScale", float(draw.model.scale));
    program_.Set("uTintLevels", options.tint_levels ? 1 : 0);
    // The input views' billboard frames, turned with the instance (scale does not change a direction).
    BillboardFrame a = FrameOf(views_[stats.views.first]), b = FrameOf(views_[stats.views.second]);
    const Eigen::Matrix3f turn = draw.model.Rotation().cast<float>();
    for (BillboardFrame* f : {&a, &b})
      f->direction = turn * f->direction, f->right = turn * f->right, f->up = turn * f->up;
    SetVec3Array(program_, "uDirection", a.direction, b.direction);
    SetVec3Array(program_, "uRight", a.right, b.right);
    SetVec3Array(program_, "uUp", a.up, b.up);
    const float weights[2] = {stats.views.first_weight, stats.views.second_weight};
    glProgramUniform1fv(program_.id(), program_.Location("uWeight"), 2, weights);

    program_.Use();
    vertex_array_.Bind();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, records_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, alpha_extents_.id());
    atlas_.Bind(0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    const bool count = options.count_fragments && (fragment_counter_ || FragmentCounter::Available());
    if (count && !fragment_counter_) fragment_counter_ = std::make_unique<FragmentCounter>();
    if (count) fragment_counter_->Begin();
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(records.size()));  // one draw per tree
    if (count) stats.fragments = int64_t(fragment_counter_->End());
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
  } else if (options.count_fragments && (fragment_counter_ || FragmentCounter::Available()))
    stats.fragments = 0;  // nothing to draw
  if (draw.finish) glFinish();
  CheckGl("render: drawing the tree");
  stats.frame_ms = Ms(start, Clock::now());
  return stats;
}

Image8 TreeRenderer::Render(const View& camera, const TreeRenderOptions& options, FrameStats* stats) {
  return RenderOffscreen(target_, camera.camera, options.background, [&] {
    const FrameStats frame = Draw(camera, options);
    if (stats) *stats = frame;
  });
}

}  // namespace voltree
