// Writes the small test scenes of the Babylon page as .glb files (node only, no packages):
//   node make_scene.mjs OUTDIR
// OUTDIR/box.glb:     a 40 x 40 m ground quad at y = 0 (normal +Y) and a 2 x 2 x 2 m box floating at
//                     y in [1.5, 3.5] over the origin; one opaque single-sided material each.
// OUTDIR/culling.glb: a 3 x 3 m single-sided quad at y = 2 over x in [5, 8], z in [-1.5, 1.5] whose
//                     front face points DOWN (-Y, away from the sun), and next to it the same quad at
//                     z in [-7.5, -4.5] facing UP. With Babylon's depth-pass culling only the up-facing
//                     quad may cast.
// OUTDIR/marker.glb:  a 0.2 m cube centred on world (1, 0, 0) (projection check).

import fs from 'node:fs';
import path from 'node:path';

function glb(meshes) {
  // meshes: [{positions: number[], normals: number[], indices: number[], color: [r,g,b,a], doubleSided}]
  const chunks = [];
  let offset = 0;
  const bufferViews = [];
  const accessors = [];
  const gltfMeshes = [];
  const materials = [];
  const nodes = [];
  const push = (typed, target) => {
    const bytes = Buffer.from(typed.buffer, typed.byteOffset, typed.byteLength);
    const pad = (4 - (bytes.length % 4)) % 4;
    bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: bytes.length, target });
    chunks.push(bytes, Buffer.alloc(pad));
    offset += bytes.length + pad;
    return bufferViews.length - 1;
  };
  meshes.forEach((m, i) => {
    const pos = new Float32Array(m.positions);
    const nrm = new Float32Array(m.normals);
    const idx = new Uint32Array(m.indices);
    const min = [Infinity, Infinity, Infinity];
    const max = [-Infinity, -Infinity, -Infinity];
    for (let k = 0; k < pos.length; k += 3)
      for (let c = 0; c < 3; ++c) { min[c] = Math.min(min[c], pos[k + c]); max[c] = Math.max(max[c], pos[k + c]); }
    const pv = push(pos, 34962);
    const nv = push(nrm, 34962);
    const iv = push(idx, 34963);
    accessors.push({ bufferView: pv, componentType: 5126, count: pos.length / 3, type: 'VEC3', min, max });
    accessors.push({ bufferView: nv, componentType: 5126, count: nrm.length / 3, type: 'VEC3' });
    accessors.push({ bufferView: iv, componentType: 5125, count: idx.length, type: 'SCALAR' });
    materials.push({ name: `mat${i}`, pbrMetallicRoughness: { baseColorFactor: m.color, metallicFactor: 0, roughnessFactor: 1 }, doubleSided: !!m.doubleSided });
    gltfMeshes.push({ name: m.name, primitives: [{ attributes: { POSITION: 3 * i, NORMAL: 3 * i + 1 }, indices: 3 * i + 2, material: i }] });
    nodes.push({ name: m.name, mesh: i });
  });
  const bin = Buffer.concat(chunks);
  const json = {
    asset: { version: '2.0', generator: 'shadowtune engines/babylon/test/make_scene.mjs' },
    scene: 0, scenes: [{ nodes: nodes.map((_, i) => i) }], nodes, meshes: gltfMeshes, materials, accessors, bufferViews,
    buffers: [{ byteLength: bin.length }],
  };
  let jsonBuf = Buffer.from(JSON.stringify(json));
  jsonBuf = Buffer.concat([jsonBuf, Buffer.alloc((4 - (jsonBuf.length % 4)) % 4, 0x20)]);
  const header = Buffer.alloc(12);
  header.writeUInt32LE(0x46546c67, 0);
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + jsonBuf.length + 8 + bin.length, 8);
  const jh = Buffer.alloc(8);
  jh.writeUInt32LE(jsonBuf.length, 0);
  jh.writeUInt32LE(0x4e4f534a, 4);
  const bh = Buffer.alloc(8);
  bh.writeUInt32LE(bin.length, 0);
  bh.writeUInt32LE(0x004e4942, 4);
  return Buffer.concat([header, jh, jsonBuf, bh, bin]);
}

// A quad from 4 corners given counter-clockwise as seen from the side its normal points to.
function quad(name, corners, normal, color) {
  return {
    name, color,
    positions: corners.flat(),
    normals: [normal, normal, normal, normal].flat(),
    indices: [0, 1, 2, 0, 2, 3],
  };
}

function box(name, [cx, cy, cz], [hx, hy, hz], color) {
  const P = [];
  const N = [];
  const I = [];
  const faces = [
    [[1, 0, 0], [0, 1, 0], [0, 0, 1]], [[-1, 0, 0], [0, 1, 0], [0, 0, -1]],
    [[0, 1, 0], [0, 0, 1], [1, 0, 0]], [[0, -1, 0], [0, 0, -1], [1, 0, 0]],
    [[0, 0, 1], [1, 0, 0], [0, 1, 0]], [[0, 0, -1], [-1, 0, 0], [0, 1, 0]],
  ];
  for (const [n, u, v] of faces) {
    // corners c + n*h +- u*h +- v*h, counter-clockwise seen from outside: u x v = n
    const base = P.length / 3;
    for (const [su, sv] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
      P.push(cx + n[0] * hx + su * u[0] * hx + sv * v[0] * hx,
             cy + n[1] * hy + su * u[1] * hy + sv * v[1] * hy,
             cz + n[2] * hz + su * u[2] * hz + sv * v[2] * hz);
      N.push(...n);
    }
    I.push(base, base + 1, base + 2, base, base + 2, base + 3);
  }
  return { name, color, positions: P, normals: N, indices: I };
}

const out = process.argv[2] ?? '.';
fs.mkdirSync(out, { recursive: true });
const G = 20;
fs.writeFileSync(path.join(out, 'box.glb'), glb([
  quad('ground', [[-G, 0, G], [G, 0, G], [G, 0, -G], [-G, 0, -G]], [0, 1, 0], [0.8, 0.8, 0.8, 1]),
  box('box', [0, 2.5, 0], [1, 1, 1], [0.8, 0.3, 0.2, 1]),
]));
fs.writeFileSync(path.join(out, 'culling.glb'), glb([
  // front face down: counter-clockwise seen from below
  quad('quad-down', [[5, 2, -1.5], [8, 2, -1.5], [8, 2, 1.5], [5, 2, 1.5]], [0, -1, 0], [0.2, 0.3, 0.8, 1]),
  // front face up: counter-clockwise seen from above
  quad('quad-up', [[5, 2, -4.5], [8, 2, -4.5], [8, 2, -7.5], [5, 2, -7.5]], [0, 1, 0], [0.2, 0.8, 0.3, 1]),
]));
fs.writeFileSync(path.join(out, 'marker.glb'), glb([box('marker', [1, 0, 0], [0.1, 0.1, 0.1], [1, 1, 0, 1])]));
console.log(`wrote ${out}/box.glb, culling.glb, marker.glb`);
