// three.js in the loop: renders a job with the CSM addon exactly as a user would set it up and reads
// back, per pixel, the shadow factor three.js's own shader computed for the sun (engines/README.md).
//
// The capture: every material keeps CSM's onBeforeCompile (CSM.setupMaterial) and we wrap it. After
// CSM's hook has run we replace `#include <lights_fragment_begin>` by CSM's own chunk text
// (CSMShader.lights_fragment_begin) with a few statements added that store the value getShadow()
// returned for the cascade the chunk picked in `stShadow` and the cascade index in `stCascade`, then
// at the very end of main() overwrite the output with (stShadow, stCascade, N.L, 1). The picture is
// rendered into a float RGBA render target cleared to (1, -1, 0, 0), so tone mapping, colour-space
// conversion, fog, dithering and premultiplication (all before our write) never touch the values,
// and the background reads coverage 0. Everything else (shadow pass, depth materials, bias, PCF,
// cascade fitting) is three.js's unmodified code.
//
// job.settings, in the CSM addon's own names (missing keys: the addon's/three.js's defaults):
//   cascades, mode ('practical'|'uniform'|'logarithmic'|'custom'), breaks (custom: fractions of the
//   shadow far, ascending, last 1), maxFar, shadowMapSize, shadowBias, normalBias, radius, lightNear,
//   lightFar, lightMargin, fade, shadowMapType ('PCFShadowMap'|'VSMShadowMap'|'BasicShadowMap'),
//   shadowSide (null = three.js's rule | 'front' | 'back' | 'double').

import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { CSM } from 'three/examples/jsm/csm/CSM.js';
import { CSMShader } from 'three/examples/jsm/csm/CSMShader.js';

// The npm version of three, put in by the driver's esbuild step (engines/lib/bundle.mjs).
const THREE_VERSION = typeof ST_PACKAGE_VERSIONS !== 'undefined' && ST_PACKAGE_VERSIONS.three ? ST_PACKAGE_VERSIONS.three : `r${THREE.REVISION}`;

const KNOWN_SETTINGS = new Set([
  'cascades', 'mode', 'breaks', 'maxFar', 'shadowMapSize', 'shadowBias', 'normalBias', 'radius',
  'lightNear', 'lightFar', 'lightMargin', 'fade', 'shadowMapType', 'shadowSide',
]);

// The CSM constructor's `data.x || default`: a falsy value (0) silently becomes the default.
const CSM_CTOR_DEFAULTS = {
  cascades: 3, maxFar: 100000, shadowMapSize: 2048, shadowBias: 0.000001,
  lightNear: 1, lightFar: 2000, lightMargin: 200,
};

const SHADOW_MAP_TYPES = {
  BasicShadowMap: THREE.BasicShadowMap,
  PCFShadowMap: THREE.PCFShadowMap,
  PCFSoftShadowMap: THREE.PCFSoftShadowMap, // three.js warns and uses PCFShadowMap
  VSMShadowMap: THREE.VSMShadowMap,
};
const SIDES = { front: THREE.FrontSide, back: THREE.BackSide, double: THREE.DoubleSide };
const SIDE_NAMES = { [THREE.FrontSide]: 'front', [THREE.BackSide]: 'back', [THREE.DoubleSide]: 'double' };

// ---------------------------------------------------------------------------------------------
// The shader hook

// Counts and applies one replacement; a mismatch means three.js's chunk changed under us.
function replaceOnce(text, pattern, replacement, what) {
  const n = typeof pattern === 'string'
    ? text.split(pattern).length - 1
    : (text.match(new RegExp(pattern.source, pattern.flags.includes('g') ? pattern.flags : pattern.flags + 'g')) || []).length;
  if (n !== 1) throw new Error(`three.js page: expected one ${what} in three.js's shader text, found ${n} (three.js ${THREE.REVISION} changed?)`);
  return text.replace(pattern, replacement);
}

// CSMShader.lights_fragment_begin with the capture statements added (CSMShader.js:181-265).
function hookedLightsChunk() {
  const src = CSMShader.lights_fragment_begin;
  const fadeStart = src.indexOf('#if defined( USE_SHADOWMAP ) && defined( CSM_FADE )');
  const plainStart = src.indexOf('#elif defined (USE_SHADOWMAP)', fadeStart);
  const plainEnd = src.indexOf('#elif ( NUM_DIR_LIGHT_SHADOWS > 0 )', plainStart);
  if (fadeStart < 0 || plainStart < 0 || plainEnd < 0) {
    throw new Error(`three.js page: CSMShader.lights_fragment_begin has an unexpected layout (three.js ${THREE.REVISION})`);
  }
  // `directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], ... ) : 1.0;`
  const getShadowStmt = /directLight\.color \*= (\( directLight\.visible && receiveShadow \) \? getShadow\( directionalShadowMap\[ i \],[^;]*? : 1\.0);/g;

  // Fade (CSMShader.js:189-239): each cascade in range adds blendRatio * mix(1, s, fadeLast ? ratio : 1)
  // of the unshadowed light (RE_Direct is linear in directLight.color and the result is mixed with
  // the previous reflectedLight by blendRatio), so the factor three.js applies is that sum.
  let fade = src.slice(fadeStart, plainStart);
  fade = replaceOnce(fade, /(#if defined\( USE_SHADOWMAP \) && defined\( CSM_FADE \)\n)/, '$1\t\tstFadeSum = 0.0; stFadeBest = 0.0;\n', 'CSM_FADE block start');
  fade = replaceOnce(fade, getShadowStmt, 'stLast = $1; directLight.color *= stLast;', 'getShadow() call in the CSM_FADE loop');
  fade = replaceOnce(fade, /(float blendRatio = shouldBlend \? ratio : 1\.0;)/,
    '$1\n\t\t\t\t\tstW = blendRatio * ( shouldFadeLastCascade ? ratio : 1.0 );\n' +
    '\t\t\t\t\tstFadeSum += blendRatio * mix( 1.0, stLast, shouldFadeLastCascade ? ratio : 1.0 );\n' +
    '\t\t\t\t\tif ( stW > stFadeBest ) { stFadeBest = stW; stCascade = float( UNROLLED_LOOP_INDEX ); }',
    'blendRatio in the CSM_FADE loop');
  fade = fade.replace(/\s*$/, '\n\t\tstShadow = stFadeSum;\n\t');

  // No fade (CSMShader.js:240-258): the cascade with CSM_cascades[i].x <= linearDepth < .y multiplies
  // the light by getShadow(); beyond the last break no cascade samples and the light is unshadowed.
  let plain = src.slice(plainStart, plainEnd);
  plain = replaceOnce(plain, getShadowStmt,
    '{ stLast = $1; directLight.color *= stLast; stShadow = stLast; stCascade = float( UNROLLED_LOOP_INDEX ); }',
    'getShadow() call in the CSM loop');

  return src.slice(0, fadeStart) + fade + plain + src.slice(plainEnd);
}

const ST_GLOBALS = 'float stShadow; float stCascade; float stLast; float stW; float stFadeSum; float stFadeBest;\n';
const ST_INIT = '\n\tstShadow = 1.0; stCascade = -1.0; stLast = 1.0; stW = 0.0; stFadeSum = 0.0; stFadeBest = 0.0;\n';

function outputStatement(lit, unorm) {
  // directionalLights[ 0 ].direction: view space, toward the light: light position - target position (src/renderers/webgl/WebGLLights.js:575-582).
  const nDotL = lit
    ? 'vec3 stSunDir = vec3( 0.0 );\n#if NUM_DIR_LIGHTS > 0\n\tstSunDir = directionalLights[ 0 ].direction;\n#endif\n\tfloat stNdotL = dot( normal, stSunDir );\n'
    : 'float stNdotL = 0.0;\n';
  const value = unorm
    ? 'vec4( clamp( stShadow, 0.0, 1.0 ), ( stCascade + 1.0 ) / 32.0, stNdotL * 0.5 + 0.5, 1.0 )'
    : 'vec4( stShadow, stCascade, stNdotL, 1.0 )';
  return `\n\t// shadowtune: the shadow factor, cascade, N.L and coverage replace the colour\n\t{\n\t${nDotL}\tgl_FragColor = ${value};\n\t}\n`;
}

// debugColour: keep three.js's own colour (alpha set to 1 for coverage) instead of the capture, for
// test/crosscheck.mjs (test/hook_crosscheck.sh), which checks that the captured factor is what three.js applies.
function patchFragmentShader(fs, chunk, unorm, debugColour) {
  const lit = fs.includes('#include <lights_fragment_begin>');
  if (lit) fs = replaceOnce(fs, '#include <lights_fragment_begin>', () => chunk, '#include <lights_fragment_begin>');
  fs = replaceOnce(fs, /void\s+main\s*\(\s*\)\s*\{/, (m) => ST_GLOBALS + m + ST_INIT, 'void main() {');
  const end = fs.lastIndexOf('}');
  const tail = debugColour ? '\n\tgl_FragColor = vec4( gl_FragColor.rgb, 1.0 );\n' : outputStatement(lit, unorm);
  fs = fs.slice(0, end) + tail + fs.slice(end);
  return { fs, lit };
}

// ---------------------------------------------------------------------------------------------
// Helpers

function settingNumber(s, key, check, what) {
  if (!(key in s)) return undefined;
  const v = s[key];
  if (typeof v !== 'number' || !Number.isFinite(v) || !check(v)) throw new Error(`three.js page: settings.${key} must be ${what}, got ${JSON.stringify(v)}`);
  return v;
}

function toBase64(bytes) {
  let bin = '';
  const CH = 0x8000;
  for (let i = 0; i < bytes.length; i += CH) bin += String.fromCharCode.apply(null, bytes.subarray(i, i + CH));
  return btoa(bin);
}

const v3 = (v) => [v.x, v.y, v.z];

// ---------------------------------------------------------------------------------------------
// The entry point (engines/README.md, "The page interface")

async function shadowtuneRender(job) {
  const warnings = [];
  // job.debug (tests only): {output: "colour"} returns three.js's linear colour instead of the
  // capture; {receiveShadow: false} turns shadow receiving off on every mesh; {forceUnorm: true}
  // takes the 8-bit fallback.
  const debug = job.debug && typeof job.debug === 'object' ? job.debug : {};
  const debugColour = debug.output === 'colour';
  const t0 = performance.now();
  const s = job.settings || {};
  for (const k of Object.keys(s)) if (!KNOWN_SETTINGS.has(k)) throw new Error(`three.js page: unknown setting ${JSON.stringify(k)} (known: ${[...KNOWN_SETTINGS].join(', ')})`);

  // --- settings -> CSM constructor data, exactly the keys the job gives
  const data = {};
  const num = {
    cascades: settingNumber(s, 'cascades', (v) => Number.isInteger(v) && v >= 1 && v <= 8, 'an integer in 1..8'),
    maxFar: settingNumber(s, 'maxFar', (v) => v > 0, 'a number > 0'),
    shadowMapSize: settingNumber(s, 'shadowMapSize', (v) => Number.isInteger(v) && v >= 1, 'a positive integer'),
    shadowBias: settingNumber(s, 'shadowBias', () => true, 'a number'),
    lightNear: settingNumber(s, 'lightNear', () => true, 'a number'),
    lightFar: settingNumber(s, 'lightFar', () => true, 'a number'),
    lightMargin: settingNumber(s, 'lightMargin', () => true, 'a number'),
  };
  for (const [k, v] of Object.entries(num)) {
    if (v === undefined) continue;
    data[k] = v;
    if (!v) warnings.push(`settings.${k} = ${v}: the CSM constructor reads it as \`data.${k} || ${CSM_CTOR_DEFAULTS[k]}\`, so it uses ${CSM_CTOR_DEFAULTS[k]}`);
  }
  const normalBias = settingNumber(s, 'normalBias', () => true, 'a number');
  const radius = settingNumber(s, 'radius', () => true, 'a number');
  if ('mode' in s) {
    if (!['practical', 'uniform', 'logarithmic', 'custom'].includes(s.mode)) throw new Error(`three.js page: settings.mode must be practical|uniform|logarithmic|custom, got ${JSON.stringify(s.mode)}`);
    data.mode = s.mode;
  }
  const cascadeCount = data.cascades || CSM_CTOR_DEFAULTS.cascades;
  if (data.mode === 'custom') {
    const b = s.breaks;
    if (!Array.isArray(b) || b.length !== cascadeCount || !b.every((x) => typeof x === 'number' && x > 0 && x <= 1) || b.some((x, i) => i > 0 && x <= b[i - 1])) {
      throw new Error(`three.js page: settings.breaks must be ${cascadeCount} ascending fractions in (0, 1] for mode "custom", got ${JSON.stringify(b)}`);
    }
    if (b[b.length - 1] !== 1) warnings.push(`settings.breaks ends at ${b[b.length - 1]}, not 1: pixels beyond it get no shadow`);
    data.customSplitsCallback = (cascades, near, far, target) => {
      for (const x of b) target.push(x);
    };
  } else if ('breaks' in s && s.breaks !== null) {
    warnings.push(`settings.breaks ignored: mode is ${JSON.stringify(data.mode || 'practical')}, not "custom"`);
  }
  if ('fade' in s && typeof s.fade !== 'boolean') throw new Error(`three.js page: settings.fade must be true or false, got ${JSON.stringify(s.fade)}`);
  let shadowMapType;
  if ('shadowMapType' in s) {
    if (!(s.shadowMapType in SHADOW_MAP_TYPES)) throw new Error(`three.js page: settings.shadowMapType must be one of ${Object.keys(SHADOW_MAP_TYPES).join('|')}, got ${JSON.stringify(s.shadowMapType)}`);
    shadowMapType = SHADOW_MAP_TYPES[s.shadowMapType];
  }
  let shadowSide = null;
  if ('shadowSide' in s && s.shadowSide !== null) {
    if (!(s.shadowSide in SIDES)) throw new Error(`three.js page: settings.shadowSide must be null|front|back|double, got ${JSON.stringify(s.shadowSide)}`);
    shadowSide = SIDES[s.shadowSide];
  }

  // --- load the scene with three.js's own glTF loader
  const scene = new THREE.Scene();
  const loader = new GLTFLoader();
  const urls = [job.scene.gltf, job.scene.extra].filter((u) => u);
  const loaded = await Promise.all(urls.map((u) => loader.loadAsync(u).catch((e) => {
    throw new Error(`three.js page: GLTFLoader failed on ${decodeURIComponent(u.replace(/^.*\//, ''))}: ${e && e.message ? e.message : e}`);
  })));
  for (const [i, g] of loaded.entries()) {
    const root = g.scene || g.scenes[0];
    if (!root) {
      warnings.push(`${urls[i].replace(/^.*\//, '')} has no scene`);
      continue;
    }
    scene.add(root);
  }
  const tLoaded = performance.now();

  // --- renderer, render target
  const { width, height } = job;
  const renderer = new THREE.WebGLRenderer({ antialias: false, alpha: false, powerPreference: 'high-performance' });
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.shadowMap.enabled = true;
  const shaderErrors = [];
  renderer.debug.onShaderError = (gl, program, vs, fs) => {
    const log = [gl.getShaderInfoLog(vs), gl.getShaderInfoLog(fs), gl.getProgramInfoLog(program)].filter((x) => x && x.trim()).join('\n').trim();
    console.error(`three.js page: shader compile/link failed:\n${log}`);
    shaderErrors.push(log.split('\n').find((l) => /ERROR/.test(l)) || log.split('\n')[0] || 'no log');
  };
  if (shadowMapType !== undefined) renderer.shadowMap.type = shadowMapType;
  const floatOk = debug.forceUnorm !== true && renderer.extensions.has('EXT_color_buffer_float');
  if (!floatOk && debugColour) throw new Error('three.js page: debug.output "colour" needs a float render target');
  if (!floatOk) warnings.push(`${debug.forceUnorm === true ? 'debug.forceUnorm' : 'EXT_color_buffer_float missing'}: read back through an 8-bit target (factor quantised to 1/255, N.L to 2/255)`);
  const target = new THREE.WebGLRenderTarget(width, height, {
    type: floatOk ? THREE.FloatType : THREE.UnsignedByteType,
    format: THREE.RGBAFormat,
    minFilter: THREE.NearestFilter,
    magFilter: THREE.NearestFilter,
    generateMipmaps: false,
    depthBuffer: true,
    samples: 0,
  });

  // --- camera
  const cam = job.camera;
  const camera = new THREE.PerspectiveCamera(cam.fovY, width / height, cam.near, cam.far);
  camera.up.set(0, 1, 0);
  camera.position.fromArray(cam.position);
  camera.lookAt(new THREE.Vector3().fromArray(cam.target));
  camera.updateMatrixWorld(true);

  // --- CSM, set up as the addon's documentation says
  const lightDirection = new THREE.Vector3().fromArray(job.sun.direction).normalize();
  const csm = new CSM({ camera, parent: scene, lightDirection, ...data });
  if ('fade' in s) csm.fade = s.fade; // the constructor ignores data.fade (CSM.js: this.fade = false)
  for (const light of csm.lights) {
    if (normalBias !== undefined) light.shadow.normalBias = normalBias;
    if (radius !== undefined) light.shadow.radius = radius;
  }

  // --- meshes and materials
  const materials = new Set();
  let meshes = 0;
  let hidden = 0;
  scene.traverse((o) => {
    if ((o.isLine || o.isPoints) && o.visible) {
      // not hooked: their colour would land in the readback; they cast no shadow by default
      o.visible = false;
      hidden++;
    }
    if (!o.isMesh) return;
    meshes++;
    o.castShadow = true;
    o.receiveShadow = debug.receiveShadow !== false;
    for (const m of Array.isArray(o.material) ? o.material : [o.material]) if (m) materials.add(m);
  });
  if (meshes === 0) warnings.push('the scene has no meshes');
  if (hidden) warnings.push(`${hidden} line/point object(s) hidden: only meshes are captured`);

  const chunk = hookedLightsChunk();
  const unorm = !floatOk;
  const unlit = new Set();
  let blended = 0;
  for (const m of materials) {
    if (shadowSide !== null) m.shadowSide = shadowSide;
    if (m.transparent && m.blending !== THREE.NoBlending) {
      // Blending would mix our values with what is behind; the shadow pass ignores blending.
      blended++;
      m.blending = THREE.NoBlending;
    }
    csm.setupMaterial(m);
    const csmHook = m.onBeforeCompile;
    m.onBeforeCompile = function (shader, r) {
      csmHook.call(this, shader, r);
      const p = patchFragmentShader(shader.fragmentShader, chunk, unorm, debugColour);
      shader.fragmentShader = p.fs;
      if (!p.lit) unlit.add(m.type);
    };
    m.needsUpdate = true;
  }
  if (blended) warnings.push(`${blended} alpha-blended material(s) drawn without blending: their pixels read the front-most blended surface`);

  csm.updateFrustums(); // after fade: the boxes and the CSM_FADE define depend on it
  csm.update();

  // --- render: shadow maps, then the picture into the float target
  renderer.autoClear = false;
  renderer.setRenderTarget(target);
  renderer.state.buffers.color.setMask(true);
  renderer.state.buffers.depth.setMask(true);
  if (unorm) renderer.state.buffers.color.setClear(1, 0, 0.5, 0);
  else renderer.state.buffers.color.setClear(1, -1, 0, 0);
  renderer.clear(true, true, true);
  renderer.render(scene, camera);

  const n = width * height * 4;
  const raw = unorm ? new Uint8Array(n) : new Float32Array(n);
  renderer.readRenderTargetPixels(target, 0, 0, width, height, raw);
  const gl = renderer.getContext();
  if (shaderErrors.length) throw new Error(`three.js page: ${shaderErrors.length} shader program(s) failed to compile: ${shaderErrors[0]}`);
  const glErr = gl.getError();
  if (glErr !== gl.NO_ERROR) throw new Error(`three.js page: WebGL error 0x${glErr.toString(16)} after the render and readback`);
  if (unlit.size) warnings.push(`unlit material(s) (${[...unlit].join(', ')}): three.js computes no shadow for them; they read factor 1, cascade -1, N.L 0`);

  // WebGL rows are bottom first: flip to top first (and decode the 8-bit fallback).
  const out = new Float32Array(n);
  const row = width * 4;
  for (let y = 0; y < height; y++) {
    const src = (height - 1 - y) * row;
    const dst = y * row;
    if (!unorm) {
      out.set(raw.subarray(src, src + row), dst);
    } else {
      for (let i = 0; i < row; i += 4) {
        if (raw[src + i + 3] === 0) {
          out.set([1, -1, 0, 0], dst + i); // background, exactly as in the float path
          continue;
        }
        out[dst + i] = raw[src + i] / 255;
        out[dst + i + 1] = Math.round((raw[src + i + 1] / 255) * 32) - 1;
        out[dst + i + 2] = (raw[src + i + 2] / 255) * 2 - 1;
        out[dst + i + 3] = raw[src + i + 3] / 255;
      }
    }
  }
  const tRendered = performance.now();

  // --- what three.js actually used, for shadowtune to compare its model with
  const shadowFar = Math.min(camera.far, csm.maxFar);
  const cascades = csm.lights.map((light, i) => {
    const sh = light.shadow;
    const c = sh.camera;
    const lo = i > 0 ? csm.breaks[i - 1] : 0;
    const hi = csm.breaks[i];
    return {
      index: i,
      breaks: [lo, hi],
      // view depths where the shader picks this cascade: linearDepth = viewZ / (shadowFar - cameraNear)
      selectDepth: [lo * (shadowFar - camera.near), hi * (shadowFar - camera.near)],
      // view depths of the frustum slice the light box is fitted to (CSMFrustum.split); slice 0 starts at near
      fitDepth: [i > 0 ? lo * shadowFar : camera.near, hi * shadowFar],
      left: c.left, right: c.right, top: c.top, bottom: c.bottom, near: c.near, far: c.far,
      position: v3(light.getWorldPosition(new THREE.Vector3())),
      target: v3(light.target.getWorldPosition(new THREE.Vector3())),
      mapSize: [sh.mapSize.x, sh.mapSize.y],
      bias: sh.bias,
      normalBias: sh.normalBias,
      radius: sh.radius,
      blurSamples: sh.blurSamples,
      intensity: sh.intensity,
      // world -> shadow map [0,1]^3 (column-major), and the light camera's world matrix (column-major)
      shadowMatrix: sh.matrix.toArray(),
      cameraMatrixWorld: c.matrixWorld.toArray(),
    };
  });
  const typeName = Object.keys(SHADOW_MAP_TYPES).find((k) => SHADOW_MAP_TYPES[k] === renderer.shadowMap.type);
  const info = {
    three: THREE_VERSION,
    revision: THREE.REVISION,
    webgl: `${gl.getParameter(gl.VERSION)}; ${(() => {
      const ext = gl.getExtension('WEBGL_debug_renderer_info');
      return ext ? gl.getParameter(ext.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
    })()}`,
    // the rasterizer's sub-pixel bits (SwiftShader: 4): engine-check's model snaps vertices alike
    subpixelBits: gl.getParameter(gl.SUBPIXEL_BITS),
    breaks: csm.breaks.slice(),
    cameraNear: camera.near,
    shadowFar,
    csm: {
      cascades: csm.cascades, mode: csm.mode, maxFar: csm.maxFar, shadowMapSize: csm.shadowMapSize,
      shadowBias: csm.shadowBias, lightNear: csm.lightNear, lightFar: csm.lightFar, lightMargin: csm.lightMargin,
      fade: csm.fade, lightDirection: v3(csm.lightDirection),
    },
    shadowMapType: typeName,
    shadowSide: shadowSide === null ? null : SIDE_NAMES[shadowSide],
    target: unorm ? 'rgba8' : 'rgba32f',
    maxTextureSize: renderer.capabilities.maxTextureSize,
    meshes,
    materials: materials.size,
  };
  for (const c of cascades) {
    if (c.mapSize[0] !== csm.shadowMapSize) warnings.push(`cascade ${c.index}: shadow map clamped to ${c.mapSize[0]} by MAX_TEXTURE_SIZE`);
  }

  const result = {
    version: THREE_VERSION,
    samples: toBase64(new Uint8Array(out.buffer)),
    cascades,
    warnings,
    info,
    timings: { loadMs: tLoaded - t0, renderMs: performance.now() - tLoaded, drawMs: tRendered - tLoaded },
  };

  csm.dispose();
  csm.remove();
  target.dispose();
  renderer.dispose();
  return result;
}

window.shadowtuneRender = shadowtuneRender;
