// Writes the driver test's scene and job:
//   node engines/test/make_scene.mjs OUTDIR [ENGINE]   -> OUTDIR/scene.glb, OUTDIR/job.json
//
// The scene (metres, +Y up), all materials single-sided:
//   ground  a 40 x 40 m quad at y = 0, facing +Y
//   box     a 2 m cube centred at (0, 3, 0)
//   fence   a 4 x 4 m quad in the plane z = -4, x in [-8, -4], y in [0, 4], facing +Z, textured with a
//           4 x 4 checker whose odd cells have alpha 0 (alphaMode MASK, cutoff 0.5, nearest sampling),
//           so alpha-tested holes must both show what is behind and let the sun through.
// The sun travels along (0.3, -1, 0.5): the box's shadow falls on the ground at +x +z of the box.
// Also exports the scene's geometry for check_samples.mjs.

import fs from 'node:fs';
import path from 'node:path';
import { encodePNG } from './png.mjs';

export const SUN = [0.3, -1, 0.5];
export const BOX = { center: [0, 3, 0], half: 1 };
export const FENCE = { x0: -8, x1: -4, y0: 0, y1: 4, z: -4, cells: 4 };
export const CAMERA = { position: [0, 12, 14], target: [0, 0, 0], fovY: 50, near: 0.5, far: 60 };
export const SIZE = { width: 320, height: 180 };

// fence cell (i along +x, j along -y from the top) is opaque when i + j is even
export function fenceCellOpaque(i, j) {
  return (i + j) % 2 === 0;
}

function checkerPNG() {
  const n = FENCE.cells;
  const px = new Uint8Array(n * n * 4);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const o = (j * n + i) * 4;
      const opaque = fenceCellOpaque(i, j);
      px[o] = opaque ? 200 : 40;
      px[o + 1] = opaque ? 60 : 40;
      px[o + 2] = 40;
      px[o + 3] = opaque ? 255 : 0;
    }
  }
  return encodePNG(n, n, px);
}

function boxGeometry(c, h) {
  const pos = [];
  const nrm = [];
  const idx = [];
  // each face: normal, two tangent axes (u x v = normal, so the winding is counter-clockwise seen from outside)
  const faces = [
    [[1, 0, 0], [0, 0, -1], [0, 1, 0]],
    [[-1, 0, 0], [0, 0, 1], [0, 1, 0]],
    [[0, 1, 0], [1, 0, 0], [0, 0, -1]],
    [[0, -1, 0], [1, 0, 0], [0, 0, 1]],
    [[0, 0, 1], [1, 0, 0], [0, 1, 0]],
    [[0, 0, -1], [-1, 0, 0], [0, 1, 0]],
  ];
  for (const [n, u, v] of faces) {
    const base = pos.length / 3;
    for (const [su, sv] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
      for (let k = 0; k < 3; k++) pos.push(c[k] + h * (n[k] + su * u[k] + sv * v[k]));
      nrm.push(...n);
    }
    idx.push(base, base + 1, base + 2, base, base + 2, base + 3);
  }
  return { pos, nrm, idx };
}

// A tiny glTF 2.0 binary writer: meshes of (positions, normals, [uvs], indices).
function writeGLB(file, meshes, materials, images) {
  const bin = [];
  let offset = 0;
  const bufferViews = [];
  const accessors = [];
  const pushView = (bytes, target) => {
    const pad = (4 - (offset % 4)) % 4;
    if (pad) {
      bin.push(Buffer.alloc(pad));
      offset += pad;
    }
    bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: bytes.length, ...(target ? { target } : {}) });
    bin.push(bytes);
    offset += bytes.length;
    return bufferViews.length - 1;
  };
  const pushAccessor = (arr, type, componentType, target, minmax) => {
    const bytes = Buffer.from(componentType === 5126 ? new Float32Array(arr).buffer : new Uint16Array(arr).buffer);
    const view = pushView(bytes, target);
    const comps = { SCALAR: 1, VEC2: 2, VEC3: 3 }[type];
    const acc = { bufferView: view, componentType, count: arr.length / comps, type };
    if (minmax) {
      acc.min = [Infinity, Infinity, Infinity];
      acc.max = [-Infinity, -Infinity, -Infinity];
      for (let i = 0; i < arr.length; i += 3) {
        for (let k = 0; k < 3; k++) {
          acc.min[k] = Math.min(acc.min[k], arr[i + k]);
          acc.max[k] = Math.max(acc.max[k], arr[i + k]);
        }
      }
    }
    accessors.push(acc);
    return accessors.length - 1;
  };
  const gltfMeshes = meshes.map((m) => {
    const attributes = {
      POSITION: pushAccessor(m.pos, 'VEC3', 5126, 34962, true),
      NORMAL: pushAccessor(m.nrm, 'VEC3', 5126, 34962),
    };
    if (m.uv) attributes.TEXCOORD_0 = pushAccessor(m.uv, 'VEC2', 5126, 34962);
    const indices = pushAccessor(m.idx, 'SCALAR', 5123, 34963);
    return { name: m.name, primitives: [{ attributes, indices, material: m.material }] };
  });
  const gltfImages = images.map((png) => ({ bufferView: pushView(png), mimeType: 'image/png' }));
  const json = {
    asset: { version: '2.0', generator: 'shadowtune engines/test/make_scene.mjs' },
    scene: 0,
    scenes: [{ nodes: gltfMeshes.map((_, i) => i) }],
    nodes: gltfMeshes.map((m, i) => ({ name: m.name, mesh: i })),
    meshes: gltfMeshes,
    materials,
    images: gltfImages,
    samplers: [{ magFilter: 9728, minFilter: 9728, wrapS: 33071, wrapT: 33071 }],
    textures: gltfImages.map((_, i) => ({ source: i, sampler: 0 })),
    buffers: [{ byteLength: 0 }],
    bufferViews,
    accessors,
  };
  let binBuf = Buffer.concat(bin);
  binBuf = Buffer.concat([binBuf, Buffer.alloc((4 - (binBuf.length % 4)) % 4)]);
  json.buffers[0].byteLength = binBuf.length;
  let jsonBuf = Buffer.from(JSON.stringify(json), 'utf8');
  jsonBuf = Buffer.concat([jsonBuf, Buffer.alloc((4 - (jsonBuf.length % 4)) % 4, 0x20)]);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0); // 'glTF'
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + jsonBuf.length + 8 + binBuf.length, 8);
  const ch = (len, type) => {
    const b = Buffer.alloc(8);
    b.writeUInt32LE(len, 0);
    b.writeUInt32LE(type, 4);
    return b;
  };
  fs.writeFileSync(file, Buffer.concat([header, ch(jsonBuf.length, 0x4e4f534a), jsonBuf, ch(binBuf.length, 0x004e4942), binBuf]));
}

export function makeScene(dir, engine = 'threejs') {
  fs.mkdirSync(dir, { recursive: true });
  const G = 20;
  const ground = {
    name: 'ground', material: 0,
    pos: [-G, 0, G, G, 0, G, G, 0, -G, -G, 0, -G],
    nrm: [0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0],
    idx: [0, 1, 2, 0, 2, 3],
  };
  const box = { name: 'box', material: 1, ...boxGeometry(BOX.center, BOX.half) };
  const f = FENCE;
  const fence = {
    name: 'fence', material: 2,
    pos: [f.x0, f.y0, f.z, f.x1, f.y0, f.z, f.x1, f.y1, f.z, f.x0, f.y1, f.z],
    nrm: [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1],
    uv: [0, 1, 1, 1, 1, 0, 0, 0],
    idx: [0, 1, 2, 0, 2, 3],
  };
  const materials = [
    { name: 'ground', pbrMetallicRoughness: { baseColorFactor: [0.6, 0.6, 0.6, 1], metallicFactor: 0, roughnessFactor: 1 } },
    { name: 'box', pbrMetallicRoughness: { baseColorFactor: [0.2, 0.4, 0.8, 1], metallicFactor: 0, roughnessFactor: 1 } },
    { name: 'fence', alphaMode: 'MASK', alphaCutoff: 0.5, pbrMetallicRoughness: { baseColorTexture: { index: 0 }, metallicFactor: 0, roughnessFactor: 1 } },
  ];
  const glb = path.join(dir, 'scene.glb');
  writeGLB(glb, [ground, box, fence], materials, [checkerPNG()]);
  const job = {
    engine,
    width: SIZE.width,
    height: SIZE.height,
    scene: { gltf: glb, extra: null },
    camera: CAMERA,
    sun: { direction: SUN },
    settings: {},
    out: path.join(dir, 'out'),
  };
  const jobFile = path.join(dir, 'job.json');
  fs.writeFileSync(jobFile, JSON.stringify(job, null, 2) + '\n');
  return { glb, jobFile };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  if (process.argv.length < 3) {
    process.stderr.write('usage: node make_scene.mjs OUTDIR [ENGINE]\n');
    process.exit(2);
  }
  const { jobFile } = makeScene(path.resolve(process.argv[2]), process.argv[3] || 'threejs');
  process.stdout.write(jobFile + '\n');
}
