// Reads back the knobs of a paste-ready snippet that `shadowtune tune --engine` wrote (threejs.js,
// babylon.js) by running it against stand-ins of the engine objects it touches, and prints them as
// the JSON of <engine>.json's "knobs" (engines/README.md lists the knob names). A snippet that does
// not run, or sets something the stand-ins do not know, exits 1 with the reason.
//   node engines/test/snippet_knobs.mjs threejs|babylon SNIPPET.js
import { readFileSync } from 'node:fs';

const [engine, file] = process.argv.slice(2);
if (!['threejs', 'babylon'].includes(engine) || !file) {
  console.error('usage: snippet_knobs.mjs threejs|babylon SNIPPET.js');
  process.exit(2);
}
const text = readFileSync(file, 'utf8');

// A stand-in that refuses properties it was not told about, so a misspelt knob fails the read.
function strict(name, known, target = {}) {
  return new Proxy(target, {
    set(o, key, value) {
      if (!known.includes(key)) throw new Error(`${name}.${String(key)} is not a knob the snippet may set`);
      o[key] = value;
      return true;
    },
  });
}

function threejs() {
  const knobs = {};
  const sides = { FrontSide: 'front', BackSide: 'back', DoubleSide: 'double' };
  const THREE = { PCFShadowMap: 'PCFShadowMap', PCFSoftShadowMap: 'PCFSoftShadowMap', BasicShadowMap: 'BasicShadowMap',
    VSMShadowMap: 'VSMShadowMap', FrontSide: 'FrontSide', BackSide: 'BackSide', DoubleSide: 'DoubleSide' };
  const renderer = { shadowMap: strict('renderer.shadowMap', ['enabled', 'type']) };
  const material = strict('material', ['shadowSide']);
  const scene = { traverse: (f) => f({ material }) };
  const shadow = strict('light.shadow', ['normalBias', 'radius']);
  let instance;
  class CSM {
    constructor(data) {
      for (const k of ['cascades', 'mode', 'maxFar', 'shadowMapSize', 'shadowBias', 'lightNear', 'lightFar', 'lightMargin'])
        knobs[k] = data[k];
      knobs.breaks = null;
      if (data.customSplitsCallback) {
        const breaks = [];
        data.customSplitsCallback(data.cascades, 0, 1, breaks);
        knobs.breaks = breaks;
      }
      this.lights = [{ shadow }];
      instance = strict('csm', ['fade'], this);
      return instance;
    }
    setupMaterial() {}
    updateFrustums() {}
  }
  const body = text.replace(/^import .*$/m, '');
  new Function('THREE', 'CSM', 'renderer', 'camera', 'scene', 'sunDirection', body)(THREE, CSM, renderer, {}, scene, {});
  Object.assign(knobs, { fade: instance.fade ?? false, normalBias: shadow.normalBias, radius: shadow.radius,
    shadowMapType: renderer.shadowMap.type, shadowSide: material.shadowSide ? sides[material.shadowSide] : null });
  return knobs;
}

function babylon() {
  let csm;
  const BABYLON = {
    ShadowGenerator: { QUALITY_LOW: 'low', QUALITY_MEDIUM: 'medium', QUALITY_HIGH: 'high' },
    CascadedShadowGenerator: class {
      constructor(mapSize) {
        this.mapSize = mapSize;
        csm = strict('csm', ['numCascades', 'lambda', 'shadowMaxZ', 'stabilizeCascades', 'depthClamp',
          'cascadeBlendPercentage', 'bias', 'normalBias', 'usePercentageCloserFiltering',
          'useContactHardeningShadow', 'filteringQuality'], this);
        return csm;
      }
      addShadowCaster() {}
    },
  };
  new Function('BABYLON', 'light', 'scene', text)(BABYLON, {}, { meshes: [{}] });
  // What the snippet leaves unset keeps Babylon's default: no shadowMaxZ (the camera's maxZ), darkness 0.
  const k = { shadowMaxZ: null, darkness: 0, ...csm };
  k.filter = k.useContactHardeningShadow ? 'PCSS' : k.usePercentageCloserFiltering === false ? 'none' : 'PCF';
  delete k.usePercentageCloserFiltering;
  delete k.useContactHardeningShadow;
  return k;
}

try {
  console.log(JSON.stringify(engine === 'threejs' ? threejs() : babylon()));
} catch (e) {
  console.error(`${file}: ${e.message}`);
  process.exit(1);
}
