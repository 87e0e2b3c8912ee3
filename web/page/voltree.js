// voltree web viewer: draws .vtree assets (one tree or a scene of instances) with WebGL2, the way
// the native renderer (render/) does: the two input views nearest in angle blended, back-to-front
// octree traversal, level of detail with hysteresis, premultiplied "over". Each function below
// names the native function it mirrors; keep them in step (docs/web.md).
// No dependencies: data.js (written by `voltree web`) defines VOLTREE_DATA before this file runs.
"use strict";

const kFormatVersion = 2;  // core/vtree.h kVtreeFormatVersion

// ---------------------------------------------------------------- the .vtree reader (core/vtree.cpp)

class AssetError extends Error {}

const kCrcTable = (() => {
  const table = new Uint32Array(256);
  for (let n = 0; n < 256; ++n) {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    table[n] = c >>> 0;
  }
  return table;
})();

function Crc32(bytes, crc = 0) {
  crc = ~crc >>> 0;
  for (let i = 0; i < bytes.length; ++i) crc = kCrcTable[(crc ^ bytes[i]) & 0xff] ^ (crc >>> 8);
  return ~crc >>> 0;
}

// Little-endian reads from a bounded span; every read is checked and every error says where.
class ByteReader {
  constructor(bytes, context) {
    this.bytes = bytes;
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.context = context;
    this.position = 0;
  }
  get remaining() { return this.bytes.length - this.position; }
  Fail(message) { throw new AssetError(`${this.context}: ${message}`); }
  Need(size, what) {
    if (size > this.remaining)
      this.Fail(`truncated: ${what} needs ${size} bytes at byte ${this.position}, only ${this.remaining} left`);
  }
  U16(what) { this.Need(2, what); const v = this.view.getUint16(this.position, true); this.position += 2; return v; }
  U32(what) { this.Need(4, what); const v = this.view.getUint32(this.position, true); this.position += 4; return v; }
  U64(what) {
    const low = this.U32(what), high = this.U32(what);
    if (high >= 0x200000) this.Fail(`${what} is too large`);
    return high * 4294967296 + low;
  }
  F32(what) { this.Need(4, what); const v = this.view.getFloat32(this.position, true); this.position += 4; return v; }
  Take(size, what) { this.Need(size, what); const v = this.bytes.subarray(this.position, this.position + size); this.position += size; return v; }
}

function TagText(tag) { return Array.from(tag, (c) => (c >= 32 && c < 127 ? String.fromCharCode(c) : "?")).join(""); }

function ReadChunk(file, name, expected) {
  if (file.remaining === 0) throw new AssetError(`${name}: truncated at byte ${file.position}: expected chunk ${expected}`);
  const offset = file.position;
  const header = file.Take(24, "chunk header");
  const fields = new ByteReader(header, name);
  const tag = TagText(fields.Take(4, "chunk tag"));
  const encoding = fields.U32("chunk encoding");
  const stored = fields.U64("chunk size"), raw = fields.U64("chunk raw size");
  const crc = file.U32("chunk checksum");
  const context = `${name}: chunk ${tag} at byte ${offset}`;
  if (tag !== expected) throw new AssetError(`${context}: unexpected chunk, expected ${expected}`);
  if (stored > file.remaining)
    throw new AssetError(`${context}: truncated, its payload needs ${stored} bytes but only ${file.remaining} remain`);
  const payload = file.Take(stored, "chunk payload");
  if (Crc32(payload, Crc32(header)) !== crc) throw new AssetError(`${context}: checksum mismatch (the file is corrupt)`);
  if (encoding === 1)
    throw new AssetError(`${context}: zstd-compressed; this page reads raw chunks (write the page with 'voltree web', which stores them raw)`);
  if (encoding !== 0) throw new AssetError(`${context}: unknown encoding ${encoding} (expected 0 raw)`);
  if (raw !== stored) throw new AssetError(`${context}: raw size ${raw} differs from stored size ${stored}`);
  return new ByteReader(payload, context);
}

function Field(object, key, context, check, expected) {
  if (!(key in object)) throw new AssetError(`${context}: missing field '${key}'`);
  if (!check(object[key])) throw new AssetError(`${context}: field '${key}' must be ${expected}`);
  return object[key];
}
const IsVec3 = (v) => Array.isArray(v) && v.length === 3 && v.every(Number.isFinite);
const IsInt = (low, high) => (v) => Number.isInteger(v) && v >= low && v <= high;

function ParseHeader(reader) {
  let header;
  try {
    header = JSON.parse(new TextDecoder().decode(reader.bytes));
  } catch (e) {
    reader.Fail("header is not a JSON object");
  }
  const c = reader.context;
  if (typeof header !== "object" || header === null) reader.Fail("header is not a JSON object");
  Field(header, "format", c, (v) => v === "voltree", "'voltree'");
  const asset = {
    levelCount: Field(header, "levels", c, IsInt(1, 17), "an integer in [1, 17]"),
    branching: Field(header, "branching", c, IsInt(2, 3), "2 or 3"),
    texels: Field(header, "texels", c, IsInt(1, 64), "an integer in [1, 64]"),
    origin: Field(header, "root_origin", c, IsVec3, "an array of 3 finite numbers"),
    size: Field(header, "root_size", c, (v) => Number.isFinite(v) && v > 0, "a positive number"),
    boundsMin: Field(header, "bounds_min", c, IsVec3, "an array of 3 finite numbers"),
    boundsMax: Field(header, "bounds_max", c, IsVec3, "an array of 3 finite numbers"),
  };
  const views = Field(header, "views", c, Array.isArray, "an array");
  asset.views = views.map((view, i) => {
    const vc = `${c}: views[${i}]`;
    if (typeof view !== "object" || view === null) throw new AssetError(`${vc}: expected an object`);
    return {
      name: String(view.name),
      position: Field(view, "position", vc, IsVec3, "an array of 3 finite numbers"),
      direction: Field(view, "direction", vc, IsVec3, "an array of 3 finite numbers"),
      up: Field(view, "up", vc, IsVec3, "an array of 3 finite numbers"),
    };
  });
  if (asset.views.length === 0) reader.Fail("the asset has no input views");
  const codebooks = Field(header, "codebooks", c, (v) => typeof v === "object" && v !== null, "an object");
  asset.colourCodebook = Field(codebooks, "colour", `${c}: codebooks`, IsInt(1, 65536), "an integer in [1, 65536]");
  asset.alphaCodebook = Field(codebooks, "alpha", `${c}: codebooks`, IsInt(1, 65536), "an integer in [1, 65536]");
  return asset;
}

// Reads `count` fields of `bits` bits (0..16), least significant bit first (core/bit_stream.h).
function ReadBits(bytes, count, bits) {
  const values = new Uint32Array(count);
  for (let i = 0, p = 0; i < count; ++i)
    for (let k = 0; k < bits; ++k, ++p) values[i] |= ((bytes[p >> 3] >> (p & 7)) & 1) << k;
  return values;
}
const BitBytes = (count, bits) => Math.ceil((count * bits) / 8);
const IndexBits = (size) => (size <= 1 ? 0 : 32 - Math.clz32(size - 1));
const IndexStreamBytes = (count, bits) => (bits > 8 ? count + BitBytes(count, bits - 8) : BitBytes(count, bits));
const Popcount = (v) => { let n = 0; for (; v; v &= v - 1) ++n; return n; };

// ParseCells: explicit coordinates or child masks of the level above (coding 0 or 1), then densities.
function ParseCells(reader, index, resolution, parent, branching) {
  if (reader.U32("level index") !== index) reader.Fail(`level index differs from ${index}`);
  const stored = reader.U32("resolution");
  if (stored !== resolution) reader.Fail(`resolution ${stored}, expected ${resolution} (branching^level)`);
  const count = reader.U32("cell count");
  if (count > resolution ** 3) reader.Fail(`cell count ${count} exceeds ${resolution ** 3} cells of the grid`);
  const coding = reader.Take(1, "cell coding")[0];
  let cells;
  if (coding === 0) {
    if (reader.remaining !== count * 10) reader.Fail(`cell count ${count} needs ${count * 10} bytes, the chunk has ${reader.remaining}`);
    cells = new Uint16Array(3 * count);
    for (let i = 0; i < 3 * count; ++i) {
      cells[i] = reader.U16("cell coordinate");
      if (cells[i] >= resolution) reader.Fail(`cell ${Math.floor(i / 3)} coordinate ${cells[i]} out of range [0, ${resolution})`);
    }
  } else if (coding === 1) {
    if (!parent) reader.Fail("cells coded as child masks, but level 0 has no parent level");
    const maskBytes = Math.ceil(branching ** 3 / 8), children = branching ** 3;
    if (reader.remaining !== parent.count * maskBytes + count * 4)
      reader.Fail(`child masks of ${parent.count} parent cells and ${count} densities need ${parent.count * maskBytes + count * 4} bytes, the chunk has ${reader.remaining}`);
    const masks = reader.Take(parent.count * maskBytes, "child masks");
    const list = [];
    for (let p = 0; p < parent.count; ++p) {
      let mask = 0;
      for (let k = 0; k < maskBytes; ++k) mask = (mask | (masks[p * maskBytes + k] << (8 * k))) >>> 0;
      if (children < 32 && mask >>> children) reader.Fail(`parent cell ${p}: child mask names children beyond the ${children} of a cell`);
      for (let k = 0; k < children; ++k)
        if ((mask >>> k) & 1)
          list.push([parent.cells[3 * p] * branching + (k % branching), parent.cells[3 * p + 1] * branching + (Math.floor(k / branching) % branching),
                     parent.cells[3 * p + 2] * branching + Math.floor(k / (branching * branching))]);
    }
    if (list.length !== count) reader.Fail(`child masks name ${list.length} cells, the cell count is ${count}`);
    list.sort((a, b) => a[2] - b[2] || a[1] - b[1] || a[0] - b[0]);  // (z, y, x), as core/vtree.cpp
    cells = new Uint16Array(3 * count);
    list.forEach((c, i) => cells.set(c, 3 * i));
  } else {
    reader.Fail(`unknown cell coding ${coding} (expected 0 explicit or 1 child masks)`);
  }
  reader.Take(4 * count, "density");  // byte planes; the page does not use density
  return { resolution, cells, count };
}

// ParseBillboards: per cell a mask of its views, then the narrow colour and alpha index streams.
function ParseBillboards(reader, index, asset, level) {
  if (reader.U32("level index") !== index) reader.Fail(`level index differs from ${index}`);
  reader.U64("billboards before pruning");
  const count = reader.U32("billboard count");
  const bits = reader.Take(2, "index bits");
  const colourBits = IndexBits(asset.colourCodebook), alphaBits = IndexBits(asset.alphaCodebook);
  if (bits[0] !== colourBits) reader.Fail(`colour indices of ${bits[0]} bits, expected ${colourBits} for ${asset.colourCodebook} codewords`);
  if (bits[1] !== alphaBits) reader.Fail(`alpha indices of ${bits[1]} bits, expected ${alphaBits} for ${asset.alphaCodebook} codewords`);
  const views = asset.views.length, maskBits = level.count * views;
  const needed = BitBytes(maskBits, 1) + IndexStreamBytes(count, colourBits) + IndexStreamBytes(count, alphaBits);
  if (reader.remaining !== needed)
    reader.Fail(`billboard count ${count} with ${level.count} cells of ${views} views needs ${needed} bytes, the chunk has ${reader.remaining}`);
  const masks = reader.Take(BitBytes(maskBits, 1), "view masks");
  let present = 0;
  for (const byte of masks) present += Popcount(byte);
  if (present !== count) reader.Fail(`view masks name ${present} billboards, the billboard count is ${count}`);
  const billboards = new Uint32Array(4 * count);  // cell, view, colour, alpha
  for (let i = 0, n = 0; i < masks.length; ++i)
    for (let k = 0; k < 8; ++k)
      if ((masks[i] >> k) & 1) {
        const bit = 8 * i + k;
        if (bit >= maskBits) reader.Fail(`view masks have bits set beyond the ${maskBits} of ${level.count} cells`);
        billboards[4 * n] = Math.floor(bit / views), billboards[4 * n + 1] = bit % views, ++n;
      }
  const indices = (bits, size, what, slot) => {
    const low = bits > 8 ? reader.Take(count, what) : null;
    const high = ReadBits(reader.Take(BitBytes(count, bits - (low ? 8 : 0)), what), count, bits - (low ? 8 : 0));
    for (let i = 0; i < count; ++i) {
      const value = low ? low[i] | (high[i] << 8) : high[i];
      if (value >= size) reader.Fail(`billboard ${i}: ${what} ${value} out of range [0, ${size})`);
      billboards[4 * i + slot] = value;
    }
  };
  indices(colourBits, asset.colourCodebook, "colour index", 2);
  indices(alphaBits, asset.alphaCodebook, "alpha index", 3);
  level.billboards = billboards;
}

function ParseAtlas(reader, asset) {
  const atlas = {
    width: reader.U32("atlas width"), height: reader.U32("atlas height"), pitch: reader.U32("tile pitch"),
    tilesPerRow: reader.U32("tiles per row"), tileCount: reader.U32("tile count"),
  };
  if (!atlas.width || !atlas.height || atlas.width % 4 || atlas.height % 4 || atlas.width > 16384 || atlas.height > 16384)
    reader.Fail(`atlas size ${atlas.width}x${atlas.height} is not a multiple of 4 in [4, 16384]`);
  const pitch = Math.ceil(asset.texels / 4) * 4;
  if (atlas.pitch !== pitch) reader.Fail(`tile pitch ${atlas.pitch}, expected ${pitch}`);
  if (!atlas.tilesPerRow || atlas.tilesPerRow * pitch > atlas.width) reader.Fail(`tiles per row ${atlas.tilesPerRow} do not fit the atlas width ${atlas.width}`);
  if (atlas.tileCount < Math.max(asset.colourCodebook, asset.alphaCodebook)) reader.Fail(`tile count ${atlas.tileCount} is less than the codebook size`);
  if (Math.ceil(atlas.tileCount / atlas.tilesPerRow) * pitch > atlas.height) reader.Fail(`${atlas.tileCount} tiles do not fit the atlas height ${atlas.height}`);
  if (reader.remaining !== atlas.width * atlas.height) reader.Fail(`DXT5 data has ${reader.remaining} bytes, expected ${atlas.width * atlas.height}`);
  atlas.dxt5 = reader.Take(atlas.width * atlas.height, "DXT5 data");
  return atlas;
}

// ParseAsset: the whole file, every count, index and checksum checked.
function ParseAsset(bytes, name) {
  const file = new ByteReader(bytes, name);
  const magic = [86, 84, 82, 69, 69, 0, 0, 0];  // "VTREE\0\0\0"
  if (bytes.length < 8 || magic.some((m, i) => bytes[i] !== m)) throw new AssetError(`${name}: not a .vtree file (missing the VTREE magic)`);
  file.Take(8, "magic");
  const version = file.U32("format version");
  if (version !== kFormatVersion)
    throw new AssetError(`${name}: format version ${version} is not supported (this page reads version ${kFormatVersion}; rebuild the asset and write the page again with this voltree)`);
  const asset = ParseHeader(ReadChunk(file, name, "HEAD"));
  asset.atlas = ParseAtlas(ReadChunk(file, name, "ATLS"), asset);  // progressive order: the atlas, then levels coarse to fine
  asset.levels = [];
  for (let i = 0, resolution = 1; i < asset.levelCount; ++i, resolution *= asset.branching) {
    const level = ParseCells(ReadChunk(file, name, "CELL"), i, resolution, asset.levels[i - 1], asset.branching);
    ParseBillboards(ReadChunk(file, name, "BBRD"), i, asset, level);
    asset.levels.push(level);
  }
  if (file.remaining !== 0) throw new AssetError(`${name}: ${file.remaining} unexpected bytes after the last chunk at byte ${file.position}`);
  return asset;
}

function DecodeBase64(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

// ---------------------------------------------------------------- vectors (Float64, like the native doubles)

const Sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const Add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const Scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const Dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const Cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const Norm = (a) => Math.sqrt(Dot(a, a));
const Normalized = (a) => Scale(a, 1 / Norm(a));

// ---------------------------------------------------------------- octree (render/traversal.cpp OctreeIndex)

class OctreeIndex {
  constructor(asset) {
    const levels = asset.levels;
    this.levels = levels.length;
    this.firstCell = [];
    let total = 0;
    for (const level of levels) this.firstCell.push(total), (total += level.count);
    this.cellCount = total;
    this.levelOf = new Uint8Array(total);
    this.centre = new Float64Array(3 * total);
    this.cellSize = levels.map((level) => asset.size / level.resolution);
    levels.forEach((level, l) => {
      for (let i = 0; i < level.count; ++i) {
        const g = this.firstCell[l] + i;
        this.levelOf[g] = l;
        for (let k = 0; k < 3; ++k) this.centre[3 * g + k] = asset.origin[k] + this.cellSize[l] * (level.cells[3 * i + k] + 0.5);
      }
    });
    // Children in storage order (the native counting sort is stable).
    const parent = new Int32Array(total).fill(-1);
    for (let l = 1; l < levels.length; ++l) {
      const above = new Map();
      const up = levels[l - 1], b = asset.branching;
      for (let i = 0; i < up.count; ++i) above.set(`${up.cells[3 * i]},${up.cells[3 * i + 1]},${up.cells[3 * i + 2]}`, this.firstCell[l - 1] + i);
      const level = levels[l];
      for (let i = 0; i < level.count; ++i) {
        const key = `${Math.floor(level.cells[3 * i] / b)},${Math.floor(level.cells[3 * i + 1] / b)},${Math.floor(level.cells[3 * i + 2] / b)}`;
        if (!above.has(key)) throw new AssetError(`level ${l} cell ${i} has no parent cell in level ${l - 1}`);
        parent[this.firstCell[l] + i] = above.get(key);
      }
    }
    this.children = Array.from({ length: total }, () => []);
    for (let c = 0; c < total; ++c) if (parent[c] >= 0) this.children[parent[c]].push(c);
    // Billboards per cell: [view, colour, alpha] triples in stored order.
    this.billboards = Array.from({ length: total }, () => []);
    this.billboardCount = 0;
    levels.forEach((level, l) => {
      for (let i = 0; i < level.billboards.length; i += 4) {
        this.billboards[this.firstCell[l] + level.billboards[i]].push(level.billboards.subarray(i + 1, i + 4));
        ++this.billboardCount;
      }
    });
  }
  Center(c) { return [this.centre[3 * c], this.centre[3 * c + 1], this.centre[3 * c + 2]]; }
  // FindBillboard: tiles (colour | alpha << 16) of (cell, view), or -1 when that view was pruned.
  FindTiles(cell, view) {
    for (const b of this.billboards[cell]) if (b[0] === view) return (b[1] | (b[2] << 16)) >>> 0;
    return -1;
  }
}

// ---------------------------------------------------------------- view choice (render/view_selection.cpp)

function SelectViews(views, centre, eye) {
  const look = Sub(centre, eye);
  let best = Infinity, second = Infinity;
  const pair = { first: 0, second: 0, firstWeight: 1, secondWeight: 0 };
  views.forEach((view, v) => {
    const toward = Sub(centre, view.position);
    const angle = Math.atan2(Norm(Cross(look, toward)), Dot(look, toward));
    if (angle < best) {
      second = best, pair.second = pair.first, best = angle, pair.first = v;
    } else if (angle < second) {
      second = angle, pair.second = v;
    }
  });
  if (views.length === 1 || best + second <= 0) {
    if (views.length === 1) pair.second = pair.first;
    return pair;
  }
  pair.firstWeight = Math.fround(second / (best + second));
  pair.secondWeight = Math.fround(1 - pair.firstWeight);
  return pair;
}

// ---------------------------------------------------------------- LOD and traversal (render/lod.cpp, traversal.cpp)

const kLod = { maxTexelPixels: 1.0, hysteresis: 0.15 };  // LodOptions defaults, screen rule

function ShouldDescend(level, finestLevel, cellSize, texels, distance, halfDiagonal, focal, previous) {
  if (level >= finestLevel) return false;
  if (distance < -halfDiagonal) return false;
  if (distance <= halfDiagonal) return true;
  const band = previous < 0 ? 1.0 : previous ? 1.0 - kLod.hysteresis : 1.0 + kLod.hysteresis;
  const texelPixels = (focal * (cellSize / Math.max(texels, 1))) / Math.max(distance, 1e-9);
  return texelPixels > kLod.maxTexelPixels * band;
}

// TraverseBackToFront: cells to draw, far to near; `refined` is the per-cell LOD history (null:
// none, each frame on its own, as `voltree eval` renders).
function TraverseBackToFront(index, eye, focal, texels, refined) {
  const out = [];
  const distance = (c) => Math.hypot(index.centre[3 * c] - eye[0], index.centre[3 * c + 1] - eye[1], index.centre[3 * c + 2] - eye[2]);
  const farToNear = (cells) => {
    const d = new Map(cells.map((c) => [c, distance(c)]));
    return cells.slice().sort((a, b) => (d.get(a) !== d.get(b) ? d.get(b) - d.get(a) : a - b));
  };
  const forget = (cell) => {
    for (const child of index.children[cell]) if (refined[child]) (refined[child] = 0), forget(child);
  };
  const visit = (cell) => {
    const level = index.levelOf[cell], size = index.cellSize[level];
    const previous = refined ? refined[cell] : -1;
    const descend = index.children[cell].length > 0 &&
      ShouldDescend(level, index.levels - 1, size, texels, distance(cell), 0.5 * Math.sqrt(3) * size, focal, previous);
    if (refined) {
      if (previous === 1 && !descend) forget(cell);
      refined[cell] = descend ? 1 : 0;
    }
    if (descend) {
      for (const child of farToNear(index.children[cell])) visit(child);
      return;
    }
    out.push(cell);
  };
  const roots = [];
  for (let c = 0; c < (index.levels > 1 ? index.firstCell[1] : index.cellCount); ++c) roots.push(c);
  for (const root of farToNear(roots)) visit(root);
  return out;
}

// ---------------------------------------------------------------- cameras (core/camera.cpp, render/orbit.cpp)

// COLMAP convention: x_cam = R x_world + t, camera X right, Y down, Z forward.
function CameraFromQuaternion(intrinsics, q, t) {
  const norm = Math.hypot(...q), [w, x, y, z] = q.map((c) => c / norm);
  const R = [
    [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
  ];
  return { ...intrinsics, R, t };
}

function LookAt(intrinsics, eye, target, up) {
  const forward = Normalized(Sub(target, eye));
  const right = Normalized(Cross(forward, up));
  const down = Cross(forward, right);
  const R = [right, down, forward];
  return { ...intrinsics, R, t: Scale([Dot(right, eye), Dot(down, eye), Dot(forward, eye)], -1) };
}

const CameraCenter = (cam) => Scale(Add(Add(Scale(cam.R[0], cam.t[0]), Scale(cam.R[1], cam.t[1])), Scale(cam.R[2], cam.t[2])), -1);

// OrbitCamerasAround for one azimuth: a pinhole whose field of view holds the sphere, times 1.1.
function OrbitCamera(orbit, width, height) {
  const e = (orbit.elevation * Math.PI) / 180, a = (orbit.azimuth * Math.PI) / 180;
  const halfFov = Math.min(Math.asin(Math.min((orbit.radius * 1.1) / orbit.distance, 0.999)), 1.5);
  const focal = (0.5 * Math.min(width, height)) / Math.tan(halfFov);
  const eye = Add(orbit.centre, Scale([Math.cos(e) * Math.cos(a), Math.cos(e) * Math.sin(a), Math.sin(e)], orbit.distance));
  return LookAt({ width, height, fx: focal, fy: focal, cx: 0.5 * width, cy: 0.5 * height }, eye, orbit.centre, [0, 0, 1]);
}

// ---------------------------------------------------------------- instances and scenes (render/instance_transform.cpp, scene_renderer.cpp)

function Instance(asset, position, degrees, scale) {
  const r = (degrees * Math.PI) / 180, c = Math.cos(r), s = Math.sin(r);
  const R = [[c, -s, 0], [s, c, 0], [0, 0, 1]];
  const rotate = (m, p) => [Dot(m[0], p), Dot(m[1], p), Dot(m[2], p)];
  const Rt = [[c, s, 0], [-s, c, 0], [0, 0, 1]];
  return {
    asset, translation: position, scale, R,
    ToWorld: (p) => Add(position, Scale(rotate(R, p), scale)),
    ToAsset: (p) => Scale(rotate(Rt, Sub(p, position)), 1 / scale),
    DirectionToWorld: (d) => rotate(R, d),
  };
}

function BoundingRadius(asset) { return asset.size * Math.max(0.5 * Math.sqrt(3), 0.5 * Math.sqrt(2)); }
function BoundingCenter(asset) { return asset.origin.map((o) => o + 0.5 * asset.size); }

// Frustum::MayIntersect for a pinhole camera.
function MayIntersect(cam, centre, radius) {
  const p = [0, 1, 2].map((k) => Dot(cam.R[k], centre) + cam.t[k]);
  const left = -cam.cx / cam.fx, right = (cam.width - cam.cx) / cam.fx;
  const top = -cam.cy / cam.fy, bottom = (cam.height - cam.cy) / cam.fy;
  const normals = [[1, 0, -left], [-1, 0, right], [0, 1, -top], [0, -1, bottom]].map(Normalized).concat([[0, 0, 1]]);
  return normals.every((n) => Dot(n, p) >= -radius);
}

// DepthRangeForSphere.
function SphereDepthRange(eye, centre, radius) {
  const distance = Norm(Sub(eye, centre));
  const near = Math.max(distance - radius, 1e-4 * radius);
  return [near, distance + radius * 1.01 + near];
}

// SceneDepthRange.
function SceneDepthRange(eye, visible, ground) {
  let nearest = Infinity, farthest = 0;
  for (const s of visible) {
    const d = Norm(Sub(s.centre, eye));
    nearest = Math.min(nearest, d - s.radius), farthest = Math.max(farthest, d + s.radius);
  }
  if (ground) {
    const lo = [ground.centre[0] - 0.5 * ground.size[0], ground.centre[1] - 0.5 * ground.size[1]];
    const hi = [ground.centre[0] + 0.5 * ground.size[0], ground.centre[1] + 0.5 * ground.size[1]];
    const closest = [Math.min(Math.max(eye[0], lo[0]), hi[0]), Math.min(Math.max(eye[1], lo[1]), hi[1]), 0];
    nearest = Math.min(nearest, Norm(Sub(closest, eye)));
    for (const x of [lo[0], hi[0]]) for (const y of [lo[1], hi[1]]) farthest = Math.max(farthest, Norm(Sub([x, y, 0], eye)));
  }
  if (farthest <= 0) return [0.01, 100];
  farthest *= 1.01;
  const near = Math.max(0.5 * nearest, 1e-3 * farthest);
  return [near, Math.max(farthest, 2 * near)];
}

// ---------------------------------------------------------------- DXT5 decoding (when the browser lacks S3TC)

function DecodeDxt5(atlas) {
  const { width, height, dxt5 } = atlas;
  const rgba = new Uint8Array(width * height * 4);
  const colours = new Uint8Array(16), alphas = new Uint8Array(8);
  let offset = 0;
  for (let by = 0; by < height; by += 4) {
    for (let bx = 0; bx < width; bx += 4, offset += 16) {
      const a0 = dxt5[offset], a1 = dxt5[offset + 1];
      alphas[0] = a0, alphas[1] = a1;
      for (let i = 1; i < 7; ++i) {
        alphas[i + 1] = a0 > a1 ? Math.floor(((7 - i) * a0 + i * a1 + 3) / 7) : i < 5 ? Math.floor(((5 - i) * a0 + i * a1 + 2) / 5) : i === 5 ? 0 : 255;
      }
      let bits = 0n;  // 48 bits of 3-bit alpha indices
      for (let i = 0; i < 6; ++i) bits |= BigInt(dxt5[offset + 2 + i]) << BigInt(8 * i);
      const c0 = dxt5[offset + 8] | (dxt5[offset + 9] << 8), c1 = dxt5[offset + 10] | (dxt5[offset + 11] << 8);
      const expand = (c) => [((c >> 11) & 31) * 255 / 31, ((c >> 5) & 63) * 255 / 63, (c & 31) * 255 / 31].map(Math.round);
      const e0 = expand(c0), e1 = expand(c1);
      for (let k = 0; k < 3; ++k) {  // DXT5's colour block is always the four-colour mode
        colours[k] = e0[k], colours[4 + k] = e1[k];
        colours[8 + k] = Math.floor((2 * e0[k] + e1[k] + 1) / 3), colours[12 + k] = Math.floor((e0[k] + 2 * e1[k] + 1) / 3);
      }
      const indices = dxt5[offset + 12] | (dxt5[offset + 13] << 8) | (dxt5[offset + 14] << 16) | (dxt5[offset + 15] << 24);
      for (let p = 0; p < 16; ++p) {
        const o = ((by + (p >> 2)) * width + bx + (p & 3)) * 4, ci = (indices >>> (2 * p)) & 3;
        rgba[o] = colours[4 * ci], rgba[o + 1] = colours[4 * ci + 1], rgba[o + 2] = colours[4 * ci + 2];
        rgba[o + 3] = alphas[Number((bits >> BigInt(3 * p)) & 7n)];
      }
    }
  }
  return rgba;
}

// ---------------------------------------------------------------- alpha extents (render/alpha_extent.cpp)

// Per atlas tile, where its alpha can be non-zero, in half-texel units of the billboard square,
// packed lo_s | lo_t << 8 | hi_s << 16 | hi_t << 24; 0 (empty) when every texel's alpha is 0. A
// texel counts as zero only when its DXT5 code is 0 in exact arithmetic, and the extent grows half
// a texel each side for the clamped bilinear fetch, so the trimmed quad never cuts a visible texel.
function AlphaTileExtents(atlas, texels) {
  const { width, dxt5, pitch, tilesPerRow, tileCount } = atlas;
  const blocksPerRow = width / 4, extents = new Uint32Array(tileCount);
  const nonZero = (block) => {  // the block's 16 texels, bit t set when texel t can be non-zero
    const a0 = dxt5[block], a1 = dxt5[block + 1];
    const zero = [a0 === 0, a1 === 0];
    for (let code = 2; code < 8; ++code) zero[code] = a0 === 0 && a1 === 0;
    if (a0 <= a1) zero[6] = true, zero[7] = false;
    let codes = 0n;
    for (let i = 0; i < 6; ++i) codes |= BigInt(dxt5[block + 2 + i]) << BigInt(8 * i);
    let mask = 0;
    for (let t = 0; t < 16; ++t) if (!zero[Number((codes >> BigInt(3 * t)) & 7n)]) mask |= 1 << t;
    return mask;
  };
  const masks = new Map();  // per block offset
  for (let tile = 0; tile < tileCount; ++tile) {
    const x0 = (tile % tilesPerRow) * pitch, y0 = Math.floor(tile / tilesPerRow) * pitch;
    let minS = texels, maxS = -1, minT = texels, maxT = -1;
    for (let t = 0; t < texels; ++t)
      for (let s = 0; s < texels; ++s) {
        const x = x0 + s, y = y0 + t, block = (Math.floor(y / 4) * blocksPerRow + Math.floor(x / 4)) * 16;
        if (!masks.has(block)) masks.set(block, nonZero(block));
        if (!((masks.get(block) >> ((y % 4) * 4 + (x % 4))) & 1)) continue;
        minS = Math.min(minS, s), maxS = Math.max(maxS, s), minT = Math.min(minT, t), maxT = Math.max(maxT, t);
      }
    if (maxS < 0) continue;
    const lo = (first) => Math.max(0, 2 * first - 1), hi = (last) => Math.min(2 * texels, 2 * last + 3);
    extents[tile] = (lo(minS) | (lo(minT) << 8) | (hi(maxS) << 16) | (hi(maxT) << 24)) >>> 0;
  }
  return extents;
}

// ---------------------------------------------------------------- shaders (render/projection.cpp, tree_renderer.cpp)

const kProjectionGlsl = `
uniform mat3 uWorldToCamera;
uniform vec3 uTranslation;
uniform vec2 uFocal, uPrincipal, uImageSize, uDepthRange;
vec4 ProjectToClip(vec3 world) {
  vec3 c = uWorldToCamera * world + uTranslation;
  float z = c.z;
  vec2 pixel_z = uFocal * c.xy + uPrincipal * z;
  vec2 ndc_z = vec2(2.0 * pixel_z.x / uImageSize.x - z, z - 2.0 * pixel_z.y / uImageSize.y);
  float n = uDepthRange.x, f = uDepthRange.y;
  return vec4(ndc_z, ((f + n) * z - 2.0 * f * n) / (f - n), z);
}
`;

const kTreeVertex = `#version 300 es
precision highp float;
precision highp int;
layout(location = 0) in vec4 aCell;     // centre (asset frame), side
layout(location = 1) in uvec4 aTiles;   // tiles of A, tiles of B, presence mask, level
layout(location = 2) in uvec2 aExtents; // alpha extents of A's and B's alpha tiles (AlphaTileExtents)
${kProjectionGlsl}
uniform vec3 uCameraRight, uCameraUp, uCameraForward, uEye, uRight[2], uUp[2];
uniform float uScale, uModelScale;
uniform int uTexels;
uniform mat3 uModelRotation;
uniform vec3 uModelTranslation;
out vec3 vWorld;
flat out vec4 vCell;
flat out uvec3 vTiles;
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
// The present views' alpha extents projected from the eye onto the quad's plane, where the
// fragment shader's rays meet them; the whole squares' bounds when a corner is behind the eye.
vec4 TrimmedBounds(vec3 centre, float side, uint mask) {
  float centre_depth = dot(centre - uEye, uCameraForward);
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  for (int k = 0; k < 2; ++k) {
    if ((mask & (1u << k)) == 0u) continue;
    uint e = k == 0 ? aExtents.x : aExtents.y;
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
  float margin = 1e-3 * side;
  return vec4(lo - margin, hi + margin);
}
void main() {
  vec3 centre = uModelTranslation + uModelScale * (uModelRotation * aCell.xyz);
  float side = uScale * aCell.w * uModelScale;
  vec4 bounds = dot(centre - uEye, uCameraForward) > 0.0 ? TrimmedBounds(centre, side, aTiles.z) : SquareBounds(side);
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  vec2 xy = mix(bounds.xy, bounds.zw, corner);
  vWorld = centre + xy.x * uCameraRight + xy.y * uCameraUp;
  vCell = vec4(centre, side);
  vLevel = int(aTiles.w);
  vTiles = aTiles.xyz;
  gl_Position = ProjectToClip(vWorld);
}
`;

const kTreeFragment = `#version 300 es
precision highp float;
precision highp int;
uniform highp sampler2D uAtlas;
uniform vec3 uEye, uDirection[2], uRight[2], uUp[2];
uniform float uWeight[2];
uniform int uTexels, uPitch, uTilesPerRow, uTintLevels;
uniform vec2 uAtlasSize;
in vec3 vWorld;
flat in vec4 vCell;
flat in uvec3 vTiles;
flat in int vLevel;
out vec4 color;
const vec3 kLevelColours[8] = vec3[8](vec3(0.9, 0.1, 0.1), vec3(0.95, 0.55, 0.1), vec3(0.95, 0.9, 0.1),
                                      vec3(0.2, 0.8, 0.2), vec3(0.1, 0.8, 0.8), vec3(0.15, 0.35, 0.95),
                                      vec3(0.6, 0.25, 0.9), vec3(0.95, 0.3, 0.8));
vec2 TileTexel(uint tile, vec2 texel) {
  vec2 origin = vec2(float(int(tile) % uTilesPerRow), float(int(tile) / uTilesPerRow)) * float(uPitch);
  return (origin + clamp(texel, vec2(0.5), vec2(float(uTexels) - 0.5))) / uAtlasSize;
}
vec4 Fetch(int k, uint tiles) {
  vec3 ray = vWorld - uEye;
  float denominator = dot(ray, uDirection[k]);
  if (abs(denominator) < 1e-12) return vec4(0.0);
  vec3 local = uEye + ray * (dot(vCell.xyz - uEye, uDirection[k]) / denominator) - vCell.xyz;
  vec2 st = vec2(dot(local, uRight[k]), -dot(local, uUp[k])) / vCell.w + 0.5;
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
`;

const kGroundCells = 32;
const kGroundVertex = `#version 300 es
precision highp float;
${kProjectionGlsl}
uniform vec2 uGroundMin, uGroundSize;
uniform int uCells;
void main() {
  const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0), ivec2(1, 1), ivec2(0, 1));
  int cell = gl_VertexID / 6;
  ivec2 ij = ivec2(cell % uCells, cell / uCells) + corners[gl_VertexID % 6];
  gl_Position = ProjectToClip(vec3(uGroundMin + uGroundSize * vec2(ij) / float(uCells), 0.0));
}
`;

const kGroundFragment = `#version 300 es
precision highp float;
uniform vec3 uColour;
out vec4 color;
void main() { color = vec4(uColour, 1.0); }
`;

function Program(gl, name, vertex, fragment) {
  const compile = (type, source) => {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`${name}: ${gl.getShaderInfoLog(shader)}`);
    return shader;
  };
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl.VERTEX_SHADER, vertex));
  gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragment));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`${name}: ${gl.getProgramInfoLog(program)}`);
  const locations = new Map();
  program.Set = (uniform, kind, ...values) => {
    if (!locations.has(uniform)) locations.set(uniform, gl.getUniformLocation(program, uniform));
    gl[`uniform${kind}`](locations.get(uniform), ...values);
  };
  return program;
}

function SetProjection(program, cam, depth) {
  // Column-major for GL: the transpose of the row-major R.
  program.Set("uWorldToCamera", "Matrix3fv", false, [0, 1, 2].flatMap((col) => [0, 1, 2].map((row) => cam.R[row][col])));
  program.Set("uTranslation", "3fv", cam.t);
  program.Set("uFocal", "2f", cam.fx, cam.fy);
  program.Set("uPrincipal", "2f", cam.cx, cam.cy);
  program.Set("uImageSize", "2f", cam.width, cam.height);
  program.Set("uDepthRange", "2f", depth[0], depth[1]);
}

// ---------------------------------------------------------------- the tree renderer (render/tree_renderer.cpp)

function BillboardFrame(view) {  // FrameOf: right = direction x up
  const d = Normalized(view.direction), up = Normalized(view.up);
  return { direction: d, right: Normalized(Cross(d, up)), up };
}

class TreeRenderer {
  constructor(gl, asset, s3tc) {
    this.gl = gl;
    this.asset = asset;
    this.index = new OctreeIndex(asset);
    this.centre = BoundingCenter(asset);
    this.program = Program(gl, "vtree billboards", kTreeVertex, kTreeFragment);
    const atlas = asset.atlas;
    this.atlas = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, this.atlas);
    if (s3tc) {
      gl.compressedTexImage2D(gl.TEXTURE_2D, 0, s3tc.COMPRESSED_RGBA_S3TC_DXT5_EXT, atlas.width, atlas.height, 0, atlas.dxt5);
    } else {
      gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, atlas.width, atlas.height, 0, gl.RGBA, gl.UNSIGNED_BYTE, DecodeDxt5(atlas));
    }
    for (const [key, value] of [[gl.TEXTURE_MIN_FILTER, gl.LINEAR], [gl.TEXTURE_MAG_FILTER, gl.LINEAR],
                                [gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE], [gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE]])
      gl.texParameteri(gl.TEXTURE_2D, key, value);
    this.gpuBytes = atlas.dxt5.length * (s3tc ? 1 : 4);
    this.alphaExtents = AlphaTileExtents(atlas, asset.texels);
    this.vertexArray = gl.createVertexArray();
    this.cellBuffer = gl.createBuffer();
    this.tileBuffer = gl.createBuffer();
    this.extentBuffer = gl.createBuffer();
    gl.bindVertexArray(this.vertexArray);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.cellBuffer);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 4, gl.FLOAT, false, 0, 0);
    gl.vertexAttribDivisor(0, 1);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.tileBuffer);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribIPointer(1, 4, gl.UNSIGNED_INT, 0, 0);
    gl.vertexAttribDivisor(1, 1);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.extentBuffer);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribIPointer(2, 2, gl.UNSIGNED_INT, 0, 0);
    gl.vertexAttribDivisor(2, 1);
    gl.bindVertexArray(null);
    const p = this.program;
    gl.useProgram(p);
    p.Set("uAtlas", "1i", 0);
    p.Set("uTexels", "1i", asset.texels);
    p.Set("uPitch", "1i", atlas.pitch);
    p.Set("uTilesPerRow", "1i", atlas.tilesPerRow);
    p.Set("uAtlasSize", "2f", atlas.width, atlas.height);
  }

  // Plan + Draw: one instanced draw call for the tree. `lodState` is this instance's history.
  Draw(cam, instance, depth, lodState, tint) {
    const gl = this.gl, index = this.index;
    const worldEye = CameraCenter(cam);
    const eye = instance.ToAsset(worldEye);
    const views = SelectViews(this.asset.views, this.centre, eye);
    const cells = TraverseBackToFront(index, eye, 0.5 * (cam.fx + cam.fy), this.asset.texels, lodState);
    const two = views.second !== views.first && views.secondWeight > 0;
    const cellData = new Float32Array(4 * cells.length), tileData = new Uint32Array(4 * cells.length);
    const extentData = new Uint32Array(2 * cells.length);
    const stats = { cells: 0, billboards: 0, minLevel: -1, maxLevel: -1, views };
    const extentOf = (tiles) => (tiles < 0 ? 0 : this.alphaExtents[tiles >>> 16]);
    // A billboard whose alpha tile is 0 everywhere draws nothing: left out, as render does.
    const drawn = (tiles) => (tiles >= 0 && extentOf(tiles) !== 0 ? tiles : -1);
    for (const cell of cells) {
      const a = drawn(index.FindTiles(cell, views.first)), b = two ? drawn(index.FindTiles(cell, views.second)) : -1;
      if (a < 0 && b < 0) continue;
      const level = index.levelOf[cell], n = stats.cells++;
      cellData.set([...index.Center(cell), index.cellSize[level]], 4 * n);
      tileData.set([Math.max(a, 0), Math.max(b, 0), (a >= 0 ? 1 : 0) | (b >= 0 ? 2 : 0), level], 4 * n);
      extentData[2 * n] = extentOf(a), extentData[2 * n + 1] = extentOf(b);
      stats.billboards += (a >= 0) + (b >= 0);
      stats.minLevel = stats.minLevel < 0 ? level : Math.min(stats.minLevel, level);
      stats.maxLevel = Math.max(stats.maxLevel, level);
    }
    if (stats.cells === 0) return stats;
    gl.bindBuffer(gl.ARRAY_BUFFER, this.cellBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, cellData.subarray(0, 4 * stats.cells), gl.STREAM_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.tileBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, tileData.subarray(0, 4 * stats.cells), gl.STREAM_DRAW);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.extentBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, extentData.subarray(0, 2 * stats.cells), gl.STREAM_DRAW);
    const p = this.program;
    gl.useProgram(p);
    SetProjection(p, cam, depth);
    p.Set("uCameraRight", "3fv", cam.R[0]);
    p.Set("uCameraUp", "3fv", Scale(cam.R[1], -1));
    p.Set("uCameraForward", "3fv", cam.R[2]);
    p.Set("uEye", "3fv", worldEye);
    p.Set("uScale", "1f", 1.0);
    p.Set("uModelRotation", "Matrix3fv", false, [0, 1, 2].flatMap((col) => [0, 1, 2].map((row) => instance.R[row][col])));
    p.Set("uModelTranslation", "3fv", instance.translation);
    p.Set("uModelScale", "1f", instance.scale);
    p.Set("uTintLevels", "1i", tint ? 1 : 0);
    const frames = [views.first, views.second].map((v) => BillboardFrame(this.asset.views[v]));
    const turned = (key) => frames.flatMap((f) => instance.DirectionToWorld(f[key]));
    p.Set("uDirection", "3fv", turned("direction"));
    p.Set("uRight", "3fv", turned("right"));
    p.Set("uUp", "3fv", turned("up"));
    p.Set("uWeight", "1fv", [views.firstWeight, views.secondWeight]);
    gl.bindVertexArray(this.vertexArray);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.atlas);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.depthMask(false);
    gl.disable(gl.CULL_FACE);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.drawArraysInstanced(gl.TRIANGLE_STRIP, 0, 4, stats.cells);
    gl.disable(gl.BLEND);
    gl.depthMask(true);
    gl.bindVertexArray(null);
    return stats;
  }
}

// ---------------------------------------------------------------- the scene (render/scene_renderer.cpp)

class SceneRenderer {
  constructor(gl, data, s3tc, lodHistory) {
    this.gl = gl;
    this.lodHistory = lodHistory;
    this.single = data.single;
    this.ground = data.ground;
    this.assets = data.assets.map((entry) => {
      let bytes;
      try {
        bytes = DecodeBase64(entry.base64);
      } catch (e) {
        throw new AssetError(`${entry.file}: the embedded data is not valid base64 (data.js is damaged)`);
      }
      return ParseAsset(bytes, entry.file);
    });
    this.bytes = data.assets.reduce((sum, entry) => sum + Math.floor((entry.base64.length * 3) / 4), 0);
    this.renderers = this.assets.map((asset, i) => {
      try {
        return new TreeRenderer(gl, asset, s3tc);
      } catch (e) {
        throw new AssetError(`${data.assets[i].file}: ${e.message}`);
      }
    });
    this.instances = data.instances.map((i) => Instance(i.asset, i.position, i.rotation, i.scale));
    this.lodStates = this.instances.map((i) => new Uint8Array(this.renderers[i.asset].index.cellCount));
    this.spheres = this.instances.map((i) => ({
      centre: i.ToWorld(BoundingCenter(this.assets[i.asset])), radius: i.scale * BoundingRadius(this.assets[i.asset]),
    }));
    if (this.ground) this.groundProgram = Program(gl, "scene ground", kGroundVertex, kGroundFragment);
    this.groundVertexArray = gl.createVertexArray();
  }

  ResetLodHistory() {
    for (const state of this.lodStates) state.fill(0);
  }

  // The camera `voltree render --orbit` starts from: OrbitCameras (one asset) or SceneOrbitCameras.
  DefaultOrbit() {
    if (this.single) {
      const asset = this.assets[0];
      const centre = Scale(Add(asset.boundsMin, asset.boundsMax), 0.5);
      const radius = Math.max(0.5 * Norm(Sub(asset.boundsMax, asset.boundsMin)), 1e-6);
      let distance = 0, elevation = 0;
      for (const view of asset.views) {
        const d = Sub(view.position, centre);
        distance += Norm(d), elevation += Math.asin(Math.min(Math.max(d[2] / Math.max(Norm(d), 1e-12), -1), 1));
      }
      distance = Math.max(distance / asset.views.length, radius * 1.1 * 1.01);
      const first = Sub(asset.views[0].position, centre);
      return { centre, radius, distance, elevation: ((elevation / asset.views.length) * 180) / Math.PI,
               azimuth: (Math.atan2(first[1], first[0]) * 180) / Math.PI };
    }
    let lo = null, hi = null;
    for (const s of this.spheres) {
      const a = Sub(s.centre, [s.radius, s.radius, s.radius]), b = Add(s.centre, [s.radius, s.radius, s.radius]);
      lo = lo ? lo.map((v, k) => Math.min(v, a[k])) : a, hi = hi ? hi.map((v, k) => Math.max(v, b[k])) : b;
    }
    const centre = Scale(Add(lo, hi), 0.5);
    const radius = Math.max(...this.spheres.map((s) => Norm(Sub(s.centre, centre)) + s.radius), 1e-6);
    return { centre, radius, distance: 1.7 * radius, elevation: 25, azimuth: -60 };
  }

  Draw(cam, background, tint) {
    const gl = this.gl;
    gl.viewport(0, 0, cam.width, cam.height);
    gl.clearColor(background[0] * background[3], background[1] * background[3], background[2] * background[3], background[3]);
    gl.clearDepth(1);
    gl.depthMask(true);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const eye = CameraCenter(cam);
    const stats = { cells: 0, billboards: 0, minLevel: -1, maxLevel: -1, drawn: 0, culled: 0, views: null };
    let order = this.instances.map((_, i) => i);
    if (!this.single) order = order.filter((i) => MayIntersect(cam, this.spheres[i].centre, this.spheres[i].radius));
    const distance = order.map((i) => Norm(Sub(this.spheres[i].centre, eye)));
    const d = new Map(order.map((i, k) => [i, distance[k]]));
    order.sort((a, b) => (d.get(a) !== d.get(b) ? d.get(b) - d.get(a) : a - b));
    stats.drawn = order.length, stats.culled = this.instances.length - order.length;
    const depth = this.single ? SphereDepthRange(eye, this.spheres[0].centre, this.spheres[0].radius)
                              : SceneDepthRange(eye, order.map((i) => this.spheres[i]), this.ground);
    if (this.ground) this.DrawGround(cam, depth);
    for (const i of order) {
      const instance = this.instances[i];
      const tree = this.renderers[instance.asset].Draw(cam, instance, depth, this.lodHistory ? this.lodStates[i] : null, tint);
      stats.cells += tree.cells, stats.billboards += tree.billboards, stats.views = tree.views;
      if (tree.minLevel >= 0) stats.minLevel = stats.minLevel < 0 ? tree.minLevel : Math.min(stats.minLevel, tree.minLevel);
      stats.maxLevel = Math.max(stats.maxLevel, tree.maxLevel);
    }
    return stats;
  }

  DrawGround(cam, depth) {
    const gl = this.gl, g = this.ground, p = this.groundProgram;
    gl.useProgram(p);
    SetProjection(p, cam, depth);
    p.Set("uGroundMin", "2f", g.centre[0] - 0.5 * g.size[0], g.centre[1] - 0.5 * g.size[1]);
    p.Set("uGroundSize", "2f", g.size[0], g.size[1]);
    p.Set("uCells", "1i", kGroundCells);
    p.Set("uColour", "3f", g.colour[0] / 255, g.colour[1] / 255, g.colour[2] / 255);
    gl.bindVertexArray(this.groundVertexArray);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.depthMask(true);
    gl.disable(gl.BLEND);
    gl.disable(gl.CULL_FACE);
    gl.drawArrays(gl.TRIANGLES, 0, 6 * kGroundCells * kGroundCells);
    gl.bindVertexArray(null);
  }
}

// ---------------------------------------------------------------- the page: URL, controls, stats

// URL parameters (all optional):
//   camera=W,H,FX,FY,CX,CY,QW,QX,QY,QZ,TX,TY,TZ  a COLMAP PINHOLE camera (cameras.txt) and pose (images.txt)
//   orbit=AZIMUTH,ELEVATION,DISTANCE              degrees, degrees, scene units about the default centre
//   background=R,G,B                              0..255, opaque (default: transparent over the page)
//   tint=1                                        colour billboards by octree level
//   history=0                                     no LOD hysteresis: each frame on its own, as `eval` renders
//   s3tc=0                                        decode DXT5 in JavaScript even when S3TC is there
//   ui=0                                          no stats line (for screenshots)
//   bench=N                                       draw N orbit frames, report the median frame time
//   size=WxH                                      canvas size in CSS pixels (default: the window)
function Numbers(params, key, count) {
  if (!params.has(key)) return null;
  const values = params.get(key).split(",").map(Number);
  if (values.length !== count || !values.every(Number.isFinite))
    throw new Error(`URL parameter '${key}' needs ${count} comma-separated numbers, got '${params.get(key)}'`);
  return values;
}

function ShowError(message) {
  const box = document.getElementById("error");
  box.textContent = `voltree: ${message}`;
  box.hidden = false;
  document.getElementById("stats").hidden = true;
  document.title = "voltree: error";
}

function Main() {
  const params = new URLSearchParams(location.search);
  if (typeof VOLTREE_DATA === "undefined") throw new Error("data.js did not load: keep it next to index.html");
  const canvas = document.getElementById("view");
  const gl = canvas.getContext("webgl2", { antialias: false, premultipliedAlpha: true, alpha: true, depth: true, preserveDrawingBuffer: true });
  if (!gl) throw new Error("this browser has no WebGL2");
  const s3tc = params.get("s3tc") === "0" ? null : gl.getExtension("WEBGL_compressed_texture_s3tc");
  const scene = new SceneRenderer(gl, VOLTREE_DATA, s3tc, params.get("history") !== "0");
  const background = params.has("background") ? [...Numbers(params, "background", 3).map((c) => c / 255), 1] : [0, 0, 0, 0];
  const tint = params.get("tint") === "1";
  const fixed = Numbers(params, "camera", 13);
  const orbit = scene.DefaultOrbit();
  const given = Numbers(params, "orbit", 3);
  if (given) [orbit.azimuth, orbit.elevation, orbit.distance] = given;
  const stats = document.getElementById("stats");
  if (params.get("ui") === "0") stats.hidden = true;

  const dpr = window.devicePixelRatio || 1;
  let useFixed = !!fixed;  // a URL camera stays until the first drag or zoom
  const Camera = () => {
    const width = Math.round(canvas.clientWidth * dpr), height = Math.round(canvas.clientHeight * dpr);
    if (canvas.width !== width || canvas.height !== height) canvas.width = width, canvas.height = height;
    if (useFixed) {  // ResizeCamera: intrinsics scaled to the canvas
      const sx = width / fixed[0], sy = height / fixed[1];
      return CameraFromQuaternion({ width, height, fx: fixed[2] * sx, fy: fixed[3] * sy, cx: fixed[4] * sx, cy: fixed[5] * sy },
                                  fixed.slice(6, 10), fixed.slice(10, 13));
    }
    return OrbitCamera(orbit, width, height);
  };
  const Describe = (frame, ms, cam) => {
    const views = frame.views && scene.single ? ` · views ${frame.views.first}+${frame.views.second} (${frame.views.firstWeight.toFixed(2)}/${frame.views.secondWeight.toFixed(2)})` : "";
    const instances = scene.single ? "" : ` · instances ${frame.drawn} drawn, ${frame.culled} culled`;
    const gpu = scene.renderers.reduce((sum, r) => sum + r.gpuBytes, 0);
    const time = ms > 0 ? `${ms.toFixed(1)} ms (${(1000 / ms).toFixed(0)} fps)` : "time not measured";  // virtual time
    stats.textContent = `${VOLTREE_DATA.name} · ${cam.width}×${cam.height} · ${time}` +
      ` · cells ${frame.cells} · billboards ${frame.billboards} · levels ${frame.minLevel}–${frame.maxLevel}${views}${instances}` +
      ` · atlas ${(gpu / 1024).toFixed(0)} KiB ${s3tc ? "S3TC" : "RGBA8 (DXT5 decoded)"} · data ${(scene.bytes / 1024).toFixed(0)} KiB`;
  };
  let drawnSize = "";
  const Frame = () => {
    const cam = Camera();
    // A new canvas size is a new view: its levels must not depend on the sizes the window passed
    // through while settling (render starts every job without history too).
    if (`${cam.width}x${cam.height}` !== drawnSize) scene.ResetLodHistory(), (drawnSize = `${cam.width}x${cam.height}`);
    const start = performance.now();
    const frame = scene.Draw(cam, background, tint);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));  // waits for the GPU, like glFinish
    const ms = performance.now() - start;
    Describe(frame, ms, cam);
    return ms;
  };

  const size = params.has("size") ? params.get("size").split("x").map(Number) : null;
  if (size) {  // a fixed canvas size in CSS pixels, whatever the window (benchmarks)
    if (size.length !== 2 || !size.every((v) => Number.isInteger(v) && v > 0))
      throw new Error(`URL parameter 'size' needs WIDTHxHEIGHT, got '${params.get("size")}'`);
    [canvas.style.width, canvas.style.height] = size.map((v) => `${v}px`);
  }
  const bench = params.has("bench") ? Number(params.get("bench")) : 0;
  if (bench > 0) {  // frames around the orbit, as `render --orbit N` times them
    Frame();
    const firstFrame = performance.now();  // since navigation: files, parsing, upload, one frame
    const times = [], azimuth = orbit.azimuth;
    for (let i = 0; i < bench; ++i) {
      orbit.azimuth = azimuth + (360 * i) / bench;
      times.push(Frame());
    }
    times.sort((a, b) => a - b);
    const median = bench % 2 ? times[(bench - 1) / 2] : 0.5 * (times[bench / 2 - 1] + times[bench / 2]);
    const frame = scene.Draw(Camera(), background, tint);
    document.getElementById("bench").textContent = JSON.stringify({
      frames: bench, width: canvas.width, height: canvas.height, median_ms: median, first_frame_ms: firstFrame,
      s3tc: !!s3tc, billboards: frame.billboards, instances_drawn: frame.drawn });
    return;
  }

  let pending = false;
  const Redraw = () => {
    if (!pending) (pending = true), requestAnimationFrame(() => ((pending = false), Frame()));
  };
  // Orbit controls: drag turns, wheel zooms, double click resets.
  let dragging = null;
  const home = { ...orbit };
  canvas.addEventListener("pointerdown", (e) => ((dragging = [e.clientX, e.clientY]), canvas.setPointerCapture(e.pointerId)));
  canvas.addEventListener("pointerup", () => (dragging = null));
  canvas.addEventListener("pointermove", (e) => {
    if (!dragging) return;
    useFixed = false;
    orbit.azimuth -= 0.4 * (e.clientX - dragging[0]);
    orbit.elevation = Math.min(89, Math.max(-89, orbit.elevation + 0.4 * (e.clientY - dragging[1])));
    dragging = [e.clientX, e.clientY];
    Redraw();
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    useFixed = false;
    orbit.distance = Math.max(orbit.radius * 0.2, orbit.distance * Math.exp(0.001 * e.deltaY));
    Redraw();
  }, { passive: false });
  canvas.addEventListener("dblclick", () => (Object.assign(orbit, home), Redraw()));
  // Drawn again in the same frame as any change of the canvas's size (a headless window settles
  // its size after load; a resized canvas is blank until drawn).
  new ResizeObserver(() => Frame()).observe(canvas);
  Frame();
}

window.addEventListener("load", () => {
  try {
    Main();
  } catch (e) {
    ShowError(e instanceof Error ? e.message : String(e));
  }
});
