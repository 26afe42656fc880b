// shadowtune's Babylon.js page: one job in, Babylon's own CascadedShadowGenerator shadow factor out.
//
// Bundled by engines/run.mjs (esbuild, iife) into a classic script; it defines
//   window.shadowtuneRender = async (job) => ({version, samples, cascades, warnings, timings, info})
// as engines/README.md "The page interface" describes: job is the README's job with scene.gltf /
// scene.extra rewritten to URLs (or null); samples is the base64 of a Float32Array width*height*4,
// rows top first, per pixel (shadow factor of light 0, cascade index or -1, N.L, coverage).
// job.settings: CascadedShadowGenerator's knobs in Babylon's names (NOTES.md "Settings"); a missing key
// keeps Babylon's default, an unknown key or a value of the wrong type fails the run.
// job.debug (tests only): {output: "colour"} keeps Babylon's own linear colour (alpha 1) instead of the
// probe; {output: "lightuv"} writes cascade 0's light coordinates (u, v, depth in [0, 1], 1) instead, to
// hold the receivers' light-space positions against the model's; {receiveShadow: false} turns shadow receiving off on every mesh; {timeoutMs} the page's own
// deadline (default 110 s, under the driver's 120 s).
//
// How the factor is read (see NOTES.md "The probe"): a MaterialPluginBase registered for every material
// appends code at CUSTOM_FRAGMENT_MAIN_END of Babylon's own PBR / Standard fragment shader. By then
// Shaders/ShadersInclude/lightFragment.js has stored light 0's factor in the shader variable `shadow`
// (lightFragment.js:238-280, after the cascade blend), and the plugin overwrites gl_FragColor with it.
// The frame is rendered into a float RGBA RenderTargetTexture (camera.outputRenderTarget) and read back
// with readPixels, so no tone mapping, image processing, fog, colour-space conversion or 8-bit
// quantisation touches it.

// Deep imports of the side-effect (non-.pure) modules: half the bundle of '@babylonjs/core' (3.6 MB
// instead of 7.6 MB minified) and the same pixels (checked bit for bit on truck-town).
import { Engine } from '@babylonjs/core/Engines/engine.js';
import { Scene } from '@babylonjs/core/scene.js';
import { Color4 } from '@babylonjs/core/Maths/math.color.js';
import { Vector3 } from '@babylonjs/core/Maths/math.vector.js';
import { UniversalCamera } from '@babylonjs/core/Cameras/universalCamera.js';
import { Camera } from '@babylonjs/core/Cameras/camera.js';
import { DirectionalLight } from '@babylonjs/core/Lights/directionalLight.js';
import { ShadowGenerator } from '@babylonjs/core/Lights/Shadows/shadowGenerator.js';
import { CascadedShadowGenerator } from '@babylonjs/core/Lights/Shadows/cascadedShadowGenerator.js';
import { MaterialPluginBase } from '@babylonjs/core/Materials/materialPluginBase.js';
import { RegisterMaterialPlugin } from '@babylonjs/core/Materials/materialPluginManager.js';
import { PBRMaterial } from '@babylonjs/core/Materials/PBR/pbrMaterial.js';
import { StandardMaterial } from '@babylonjs/core/Materials/standardMaterial.js';
import { ShaderLanguage } from '@babylonjs/core/Materials/shaderLanguage.js';
import { RenderTargetTexture } from '@babylonjs/core/Materials/Textures/renderTargetTexture.js';
import { Constants } from '@babylonjs/core/Engines/constants.js';
import { Logger } from '@babylonjs/core/Misc/logger.js';
import { ImportMeshAsync } from '@babylonjs/core/Loading/sceneLoader.js';
import '@babylonjs/loaders/glTF/index.js';

const B = {
  Engine, Scene, Color4, Vector3, UniversalCamera, Camera, DirectionalLight, ShadowGenerator, CascadedShadowGenerator,
  MaterialPluginBase, RegisterMaterialPlugin, PBRMaterial, StandardMaterial, ShaderLanguage, RenderTargetTexture,
  Constants, Logger, ImportMeshAsync,
};

const VERSION = B.Engine.Version; // "9.28.0"

// ---------------------------------------------------------------------------------------------
// The probe: overwrite the fragment colour with (shadow, cascade, N.L, 1) at the very end of main().
// No // comments inside: Babylon's shader processor may join lines. Notes on the GLSL below:
// - 'shadow' is declared by pbrBlockDirectLighting.js:20 (PBR) or default.fragment.js:169 (Standard) and
//   written last by lightFragment<0>: = computeShadowWithCSMPCF*(...) (lightFragment.js:238-242), then
//   mixed with the next cascade in the blend band (lightFragment.js:259-280); stays 1 beyond the last
//   cascade (index0 == -1, lightFragment.js:232-235).
// - the cascade loop is Babylon's own selection (lightFragment.js:224-231), repeated because the blend
//   step increments index0 (lightFragment.js:260).
// - the normal is PBR's geometricNormalW (pbrBlockNormalGeometric.js:6-12): normalize(vNormalW), flipped on
//   back faces of two-sided materials; L = -light0.vLightData.xyz (the light's direction, toward the sun).

const PROBE_FRAGMENT = `
{
    float stShadow = 1.0;
    float stCascade = -1.0;
#if defined(LIGHT0) && !defined(UNLIT)
    stShadow = shadow;
#endif
#if defined(SHADOW0) && defined(SHADOWCSM0)
#ifdef SHADOWCSMUSESHADOWMAXZ0
    int stIndex = -1;
#else
    int stIndex = SHADOWCSMNUM_CASCADES0 - 1;
#endif
    for (int i = 0; i < SHADOWCSMNUM_CASCADES0; i++) {
#ifdef SHADOWCSM_RIGHTHANDED0
        float stDiff = viewFrustumZ0[i] + vPositionFromCamera0.z;
#else
        float stDiff = viewFrustumZ0[i] - vPositionFromCamera0.z;
#endif
        if (stDiff >= 0.) { stIndex = i; break; }
    }
    stCascade = float(stIndex);
#endif
    float stNdotL = 0.0;
#if defined(LIGHT0) && defined(DIRLIGHT0)
#ifdef PBR
    vec3 stN = geometricNormalW;
#elif defined(NORMAL)
    vec3 stN = normalize(vNormalW);
#ifdef TWOSIDEDLIGHTING
    stN = gl_FrontFacing ? stN : -stN;
#endif
#else
    vec3 stN = vec3(0.0);
#endif
    stNdotL = dot(stN, normalize(-light0.vLightData.xyz));
#endif
#ifdef SHADOWTUNE_LIGHTUV
    {
        vec4 stP = vPositionFromLight0[0];
        vec3 stC = stP.xyz / stP.w;
        gl_FragColor = vec4(0.5 * stC + 0.5, 1.0);
    }
#elif defined(SHADOWTUNE_COLOUR)
    gl_FragColor = vec4(gl_FragColor.rgb, 1.0);
#else
    gl_FragColor = vec4(stShadow, stCascade, stNdotL, 1.0);
#endif
}
`;

let probeLightUv = false;
let probeColour = false; // job.debug.output === "colour": set before the job's materials exist

class ShadowtuneProbePlugin extends B.MaterialPluginBase {
  constructor(material) {
    super(material, 'ShadowtuneProbe', 1000, { SHADOWTUNE_PROBE: false, SHADOWTUNE_COLOUR: false, SHADOWTUNE_LIGHTUV: false });
    this._enable(true);
  }
  prepareDefines(defines) {
    defines.SHADOWTUNE_PROBE = true;
    defines.SHADOWTUNE_COLOUR = probeColour;
    defines.SHADOWTUNE_LIGHTUV = probeLightUv;
  }
  getClassName() {
    return 'ShadowtuneProbePlugin';
  }
  isCompatible(shaderLanguage) {
    return shaderLanguage === B.ShaderLanguage.GLSL;
  }
  getCustomCode(shaderType) {
    if (shaderType !== 'fragment') return null;
    return { CUSTOM_FRAGMENT_MAIN_END: PROBE_FRAGMENT };
  }
}

let probeRegistered = false;
function registerProbe() {
  if (probeRegistered) return;
  probeRegistered = true;
  B.RegisterMaterialPlugin('ShadowtuneProbe', (material) =>
    material instanceof B.PBRMaterial || material instanceof B.StandardMaterial ? new ShadowtuneProbePlugin(material) : null);
}

// ---------------------------------------------------------------------------------------------
// Settings: Babylon's knob names; a missing key keeps Babylon's default.

const FILTERS = {
  none: B.ShadowGenerator.FILTER_NONE,
  pcf: B.ShadowGenerator.FILTER_PCF,
  pcss: B.ShadowGenerator.FILTER_PCSS,
};
const QUALITIES = {
  high: B.ShadowGenerator.QUALITY_HIGH,
  medium: B.ShadowGenerator.QUALITY_MEDIUM,
  low: B.ShadowGenerator.QUALITY_LOW,
};
const FILTER_NAMES = Object.fromEntries(Object.entries(FILTERS).map(([k, v]) => [v, k === 'none' ? 'none' : k.toUpperCase()]));
const QUALITY_NAMES = Object.fromEntries(Object.entries(QUALITIES).map(([k, v]) => [v, k]));

const KNOWN = new Set([
  'mapSize', 'numCascades', 'lambda', 'shadowMaxZ', 'stabilizeCascades', 'depthClamp', 'autoCalcDepthBounds',
  'cascadeBlendPercentage', 'freezeShadowCastersBoundingInfo', 'bias', 'normalBias', 'filter', 'filteringQuality',
  'darkness', 'penumbraDarkness', 'contactHardeningLightSizeUVRatio', 'frustumEdgeFalloff', 'forceBackFacesOnly',
  'transparencyShadow', 'enableSoftTransparentShadow', 'useFloat32TextureType', 'lightMinZ', 'lightMaxZ',
  'minDistance', 'maxDistance',
]);

const BOOLEAN_KEYS = new Set(['stabilizeCascades', 'depthClamp', 'autoCalcDepthBounds', 'freezeShadowCastersBoundingInfo',
  'forceBackFacesOnly', 'transparencyShadow', 'enableSoftTransparentShadow', 'useFloat32TextureType']);

// The value of settings[key] (undefined when missing or null), checked: a number, or a boolean for
// BOOLEAN_KEYS; anything else throws (the driver reports it, exit 1).
function setting(settings, key) {
  const v = settings[key];
  if (v === undefined || v === null) return undefined;
  if (BOOLEAN_KEYS.has(key)) {
    if (typeof v !== 'boolean') throw new Error(`babylon page: settings.${key} must be true or false, got ${JSON.stringify(v)}`);
  } else if (typeof v !== 'number' || !Number.isFinite(v)) {
    throw new Error(`babylon page: settings.${key} must be a finite number, got ${JSON.stringify(v)}`);
  }
  return v;
}

function parseFilter(v) {
  if (v === undefined || v === null) return undefined;
  const key = String(v).toLowerCase().replace(/^filter_/, '');
  if (typeof v === 'string' && key in FILTERS) return FILTERS[key];
  throw new Error(`babylon page: settings.filter must be "PCF", "PCSS" or "none" (CascadedShadowGenerator supports no other), got ${JSON.stringify(v)}`);
}

function parseQuality(v) {
  if (v === undefined || v === null) return undefined;
  const key = String(v).toLowerCase().replace(/^quality_/, '');
  if (typeof v === 'string' && key in QUALITIES) return QUALITIES[key];
  throw new Error(`babylon page: settings.filteringQuality must be "low", "medium" or "high", got ${JSON.stringify(v)}`);
}

// ---------------------------------------------------------------------------------------------

function nextFrame() {
  return new Promise((resolve) => requestAnimationFrame(() => resolve()));
}

function toBase64(bytes) {
  let s = '';
  const chunk = 0x8000;
  for (let i = 0; i < bytes.length; i += chunk) s += String.fromCharCode.apply(null, bytes.subarray(i, i + chunk));
  return btoa(s);
}

function extOf(url) {
  const m = /\.(gltf|glb)(?:[?#].*)?$/i.exec(url);
  return m ? '.' + m[1].toLowerCase() : undefined;
}

function vec(a, name) {
  if (!Array.isArray(a) || a.length !== 3 || !a.every((x) => typeof x === 'number' && Number.isFinite(x)))
    throw new Error(`job.${name} must be [x, y, z] numbers`);
  return new B.Vector3(a[0], a[1], a[2]);
}

const arr = (m) => Array.from(m.m ?? m); // Babylon Matrix.m: column-major (GL) for clip = M * [x y z 1]
const v3 = (v) => [v.x, v.y, v.z];

function cascadeReport(gen) {
  const n = gen.numCascades;
  const out = [];
  for (let i = 0; i < n; ++i) {
    const c = gen._cascades[i];
    const cameraRange = gen._getCamera().maxZ - gen._getCamera().minZ;
    out.push({
      index: i,
      // view depths (planar, along the camera axis) where the slice starts and ends
      splitNear: gen._getCamera().minZ + c.prevBreakDistance * cameraRange,
      splitFar: gen._viewSpaceFrustumsZ[i],
      prevBreakDistance: c.prevBreakDistance,
      breakDistance: c.breakDistance,
      frustumLength: gen._frustumLengths[i],
      // light space (LookAtLH from shadowCameraPos toward frustumCenter): x/y box of the slice,
      // z = the depth range the projection maps to [-1, 1] (after the caster tightening)
      minExtents: v3(gen.getCascadeMinExtents(i)),
      maxExtents: v3(gen.getCascadeMaxExtents(i)),
      frustumCenter: v3(gen._frustumCenter[i]),
      shadowCameraPos: v3(gen._shadowCameraPos[i]),
      sliceCornersWorld: gen._frustumCornersWorldSpace[i].map(v3),
      viewMatrix: arr(gen.getCascadeViewMatrix(i)),
      projectionMatrix: arr(gen.getCascadeProjectionMatrix(i)), // includes the texel-snapping translation
      transformMatrix: arr(gen.getCascadeTransformMatrix(i)), // projection * view: world -> light clip
      lightMatrixFloat32: Array.from(gen._transformMatricesAsArray.subarray(i * 16, i * 16 + 16)), // what the shader gets
    });
  }
  return out;
}

// Rejects when `promise` has not settled by `deadline` (performance.now() ms) or Babylon logged an error.
async function withDeadline(promise, deadline, what, errors) {
  let timer;
  const timeout = new Promise((_, reject) => {
    const check = () => {
      if (errors.length) reject(new Error(`${what}: Babylon reported errors: ${errors.slice(0, 3).join(' | ').slice(0, 2000)}`));
      else if (performance.now() > deadline) reject(new Error(`${what}: timed out`));
      else timer = setTimeout(check, 50);
    };
    check();
  });
  try {
    return await Promise.race([promise, timeout]);
  } finally {
    clearTimeout(timer);
  }
}

async function render(job) {
  const t0 = performance.now();
  const debug = job.debug && typeof job.debug === 'object' ? job.debug : {};
  const deadline = t0 + (debug.timeoutMs ?? 110000);
  const warnings = [];
  const errors = [];
  const onLog = () => {
    for (const e of B.Logger.LogCache.split('\n')) if (/error/i.test(e) && !errors.includes(e)) errors.push(e.replace(/<[^>]*>/g, ''));
  };
  B.Logger.ClearLogCache();
  B.Logger.OnNewCacheEntry = onLog;
  const width = job.width | 0;
  const height = job.height | 0;
  if (!(width > 0 && height > 0)) throw new Error('job.width and job.height must be positive integers');
  const settings = job.settings ?? {};
  for (const k of Object.keys(settings)) {
    if (!KNOWN.has(k)) throw new Error(`babylon page: unknown setting "${k}" (known: ${[...KNOWN].join(', ')})`);
  }
  probeColour = debug.output === 'colour';
  probeLightUv = debug.output === 'lightuv';

  registerProbe();

  // Canvas and engine: WebGL2, no antialiasing, no hardware scaling.
  let canvas = document.getElementById('shadowtune-canvas');
  if (canvas) canvas.remove();
  canvas = document.createElement('canvas');
  canvas.id = 'shadowtune-canvas';
  canvas.width = width;
  canvas.height = height;
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  document.body.style.margin = '0';
  document.body.appendChild(canvas);
  const engine = new B.Engine(canvas, false, {
    antialias: false, stencil: true, preserveDrawingBuffer: false, premultipliedAlpha: false,
    disableWebGL2Support: false, doNotHandleContextLost: true, audioEngine: false,
  }, false);
  try {
    if (engine.webGLVersion !== 2) throw new Error(`WebGL2 is required, got WebGL${engine.webGLVersion}`);
    engine.setHardwareScalingLevel(1);
    engine.setSize(width, height);
    const caps = engine.getCaps();
    if (!caps.textureFloatRender) throw new Error('float render targets (EXT_color_buffer_float) are not supported');
    if (!B.CascadedShadowGenerator.IsSupported) throw new Error('CascadedShadowGenerator.IsSupported is false on this engine');

    const scene = new B.Scene(engine);
    scene.useRightHandedSystem = true; // glTF's right-handed world, no __root__ z flip (glTFLoader.pure.js:565)
    scene.clearColor = new B.Color4(0, 0, 0, 0);
    scene.autoClear = true;
    scene.fogEnabled = false;
    // Image processing 'by post process' with no post process: materials write linear colour, clamped to
    // [0, 30] (pbrBlockImageProcessing.js:4-7), instead of applyImageProcessing's toGammaSpace + saturate.
    // Only debug.output "colour" sees it: the probe overwrites the colour.
    scene.imageProcessingConfiguration.isEnabled = true;
    scene.imageProcessingConfiguration.applyByPostProcess = true;
    scene.skipPointerMovePicking = true;

    // Camera: FreeCamera-family UniversalCamera, vertical fov in radians, near/far as given.
    const cam = job.camera ?? {};
    const camera = new B.UniversalCamera('shadowtune-camera', vec(cam.position, 'camera.position'), scene);
    camera.setTarget(vec(cam.target, 'camera.target'));
    camera.fovMode = B.Camera.FOVMODE_VERTICAL_FIXED;
    camera.fov = (cam.fovY * Math.PI) / 180;
    camera.minZ = cam.near;
    camera.maxZ = cam.far;
    camera.inertia = 0;
    scene.activeCamera = camera;

    // The sun.
    const dir = vec(job.sun?.direction, 'sun.direction').normalize();
    const light = new B.DirectionalLight('sun', dir, scene);
    light.intensity = 1;

    // The geometry, with the loader's own materials.
    const tLoad0 = performance.now();
    for (const key of ['gltf', 'extra']) {
      const url = job.scene?.[key];
      if (!url) continue;
      await withDeadline(B.ImportMeshAsync(url, scene, { pluginExtension: extOf(url), pluginOptions: { gltf: { animationStartMode: 0 } } }), deadline, `loading ${url}`, []);
    }
    const tLoad1 = performance.now();
    for (const m of scene.meshes) m.computeWorldMatrix(true); // world boxes current before anything reads them
    const meshes = scene.meshes.filter((m) => m.getTotalVertices() > 0);
    if (meshes.length === 0) throw new Error('the job has no geometry (scene.gltf and scene.extra are empty or null)');
    for (const m of meshes) m.receiveShadows = debug.receiveShadow !== false;
    for (const mat of scene.materials) {
      if (mat.needAlphaBlending && mat.needAlphaBlending()) {
        warnings.push(`material "${mat.name}" is alpha-blended: drawn without blending here, and (transparencyShadow false) it casts no shadow`);
        mat.alphaMode = B.Constants.ALPHA_DISABLE;
      }
    }

    // The generator, created after the camera so shadowMaxZ defaults to camera.maxZ
    // (cascadedShadowGenerator.pure.js:547).
    const mapSize = setting(settings, 'mapSize') ?? 1024;
    const usefulFloatFirst = setting(settings, 'useFloat32TextureType');
    const gen = new B.CascadedShadowGenerator(mapSize, light, usefulFloatFirst, camera);
    const set = (key, fn) => {
      const v = setting(settings, key);
      if (v !== undefined) fn(v);
    };
    set('numCascades', (v) => { gen.numCascades = v; if (gen.numCascades !== v) warnings.push(`numCascades ${v} clamped to ${gen.numCascades} (2..4)`); });
    set('lambda', (v) => { gen.lambda = v; });
    set('shadowMaxZ', (v) => {
      gen.shadowMaxZ = v;
      if (gen.shadowMaxZ !== v) warnings.push(`shadowMaxZ ${v} ignored by Babylon (outside [camera.minZ, camera.maxZ]); it stays ${gen.shadowMaxZ}`);
    });
    set('stabilizeCascades', (v) => { gen.stabilizeCascades = v; });
    set('depthClamp', (v) => { gen.depthClamp = v; });
    set('cascadeBlendPercentage', (v) => { gen.cascadeBlendPercentage = v; });
    set('bias', (v) => { gen.bias = v; });
    set('normalBias', (v) => { gen.normalBias = v; });
    const filter = parseFilter(settings.filter);
    if (filter !== undefined) gen.filter = filter;
    const quality = parseQuality(settings.filteringQuality);
    if (quality !== undefined) gen.filteringQuality = quality;
    set('darkness', (v) => { gen.darkness = v; });
    set('penumbraDarkness', (v) => { gen.penumbraDarkness = v; });
    set('contactHardeningLightSizeUVRatio', (v) => { gen.contactHardeningLightSizeUVRatio = v; });
    set('frustumEdgeFalloff', (v) => { gen.frustumEdgeFalloff = v; });
    set('forceBackFacesOnly', (v) => { gen.forceBackFacesOnly = v; });
    set('transparencyShadow', (v) => { gen.transparencyShadow = v; });
    set('enableSoftTransparentShadow', (v) => { gen.enableSoftTransparentShadow = v; });
    const minD = setting(settings, 'minDistance');
    const maxD = setting(settings, 'maxDistance');
    if (minD !== undefined || maxD !== undefined) gen.setMinMaxDistance(minD ?? 0, maxD ?? 1);
    const lightMinZ = setting(settings, 'lightMinZ');
    const lightMaxZ = setting(settings, 'lightMaxZ');
    if (lightMinZ !== undefined) light.shadowMinZ = lightMinZ;
    if (lightMaxZ !== undefined) light.shadowMaxZ = lightMaxZ;
    if (lightMinZ !== undefined || lightMaxZ !== undefined)
      warnings.push('lightMinZ/lightMaxZ set on the light, but CascadedShadowGenerator never reads light.shadowMinZ/shadowMaxZ (NOTES.md)');

    const renderList = gen.getShadowMap().renderList;
    for (const m of meshes) renderList.push(m);
    set('freezeShadowCastersBoundingInfo', (v) => { gen.freezeShadowCastersBoundingInfo = v; }); // after the list: freezing computes the box now
    set('autoCalcDepthBounds', (v) => { gen.autoCalcDepthBounds = v; });

    // Where the frame goes: a float RGBA target of the canvas size, no mipmaps, nearest sampling.
    const target = new B.RenderTargetTexture('shadowtune-probe', { width, height }, scene, {
      generateMipMaps: false, type: B.Constants.TEXTURETYPE_FLOAT, format: B.Constants.TEXTUREFORMAT_RGBA,
      samplingMode: B.Constants.TEXTURE_NEAREST_SAMPLINGMODE, generateDepthBuffer: true, generateStencilBuffer: false, samples: 1,
    });
    camera.outputRenderTarget = target;

    // Compile everything, then render.
    const tRender0 = performance.now();
    await withDeadline(gen.forceCompilationAsync(), deadline, 'compiling the shadow-map shaders', errors);
    await withDeadline(scene.whenReadyAsync(true), deadline, 'waiting for the scene to be ready', errors);
    if (errors.length) throw new Error(`Babylon reported errors: ${errors.slice(0, 3).join(' | ').slice(0, 2000)}`);
    const tCompiled = performance.now();
    let frames = 0;
    const renderFrame = async () => {
      if (performance.now() > deadline) throw new Error(`rendering: timed out after ${frames} frames`);
      scene.render();
      frames++;
      await nextFrame();
      if (errors.length) throw new Error(`Babylon reported errors: ${errors.slice(0, 3).join(' | ').slice(0, 2000)}`);
    };
    // One frame is the result: the casters' box is computed in onBeforeRender (cascadedShadowGenerator.pure.js:60)
    // from world boxes that are current because every world matrix is computed here first; the shadow
    // maps are rendered before the camera in the same scene.render(). A frame is only repeated while the
    // scene is not ready (shaders, textures) and, for autoCalcDepthBounds, until the asynchronous depth
    // reduction has reported. debug.frames (tests) renders that many frames instead.
    for (const m of scene.meshes) m.computeWorldMatrix(true);
    for (let i = 0; i < 200 && !scene.isReady(true); ++i) await renderFrame();
    if (gen.autoCalcDepthBounds) {
      let last = null;
      for (let i = 0; i < 30; ++i) {
        await renderFrame();
        const now = `${gen.minDistance},${gen.maxDistance}`;
        if (now === last && !(gen.minDistance === 0 && gen.maxDistance === 1 && i < 10)) break;
        last = now;
      }
      if (gen.minDistance === 0 && gen.maxDistance === 1) warnings.push('autoCalcDepthBounds: the depth reduction never reported; breaks use minDistance 0, maxDistance 1');
    }
    const finalFrames = Number.isInteger(debug.frames) && debug.frames > 0 ? debug.frames : 1;
    for (let i = 0; i < finalFrames; ++i) await renderFrame();
    const tFramed = performance.now();
    const pixels = await target.readPixels(0, 0, null, true, true);
    const tRender1 = performance.now();
    if (!(pixels instanceof Float32Array) || pixels.length !== width * height * 4)
      throw new Error(`readPixels returned ${pixels?.constructor?.name} of ${pixels?.length}, expected Float32Array of ${width * height * 4}`);

    // readPixels is bottom row first (GL); flip. Background: factor 1, cascade -1, N.L 0, coverage 0.
    const out = new Float32Array(width * height * 4);
    for (let y = 0; y < height; ++y) {
      const src = (height - 1 - y) * width * 4;
      out.set(pixels.subarray(src, src + width * 4), y * width * 4);
    }
    for (let i = 0; i < out.length; i += 4) {
      if (out[i + 3] === 0) { out[i] = 1; out[i + 1] = -1; out[i + 2] = 0; }
      else out[i + 3] = 1;
    }

    const camInfo = {
      viewMatrix: arr(camera.getViewMatrix()),
      projectionMatrix: arr(camera.getProjectionMatrix()),
    };
    const result = {
      version: VERSION,
      samples: toBase64(new Uint8Array(out.buffer)),
      cascades: cascadeReport(gen),
      warnings,
      timings: { loadMs: tLoad1 - tLoad0, renderMs: tRender1 - tRender0 },
      info: {
        frames,
        // the rasterizer's sub-pixel bits (SwiftShader: 4): engine-check's model snaps vertices alike
        subpixelBits: engine._gl.getParameter(engine._gl.SUBPIXEL_BITS),
        // page-side phases: shader compilation (forceCompilation + whenReady), the frames, readPixels
        phasesMs: { compile: tCompiled - tRender0, frames: tFramed - tCompiled, readback: tRender1 - tFramed },
        pageTotalMs: performance.now() - t0,
        generator: {
          mapSize: gen.mapSize, numCascades: gen.numCascades, lambda: gen.lambda, shadowMaxZ: gen.shadowMaxZ,
          stabilizeCascades: gen.stabilizeCascades, depthClamp: gen.depthClamp, autoCalcDepthBounds: gen.autoCalcDepthBounds,
          cascadeBlendPercentage: gen.cascadeBlendPercentage, freezeShadowCastersBoundingInfo: gen.freezeShadowCastersBoundingInfo,
          bias: gen.bias, normalBias: gen.normalBias, filter: FILTER_NAMES[gen.filter] ?? gen.filter,
          filteringQuality: QUALITY_NAMES[gen.filteringQuality] ?? gen.filteringQuality, darkness: gen.darkness,
          penumbraDarkness: gen.penumbraDarkness, frustumEdgeFalloff: gen.frustumEdgeFalloff,
          contactHardeningLightSizeUVRatio: gen.contactHardeningLightSizeUVRatio, forceBackFacesOnly: gen.forceBackFacesOnly,
          minDistance: gen.minDistance, maxDistance: gen.maxDistance,
          lightDirection: v3(gen._lightDirection),
          viewSpaceFrustumsZ: Array.from(gen._viewSpaceFrustumsZ),
          frustumLengths: Array.from(gen._frustumLengths),
          // the union of the render list's world AABBs (cascadedShadowGenerator.pure.js:67-83)
          castersBoxWorld: { min: v3(gen._scbiMin), max: v3(gen._scbiMax) },
          // 0 UNSIGNED_BYTE, 1 FLOAT, 2 HALF_FLOAT: the colour (RED) layer, read only by filter none / PCSS
          shadowMapTextureType: gen._textureType,
          depthTexture: 'DEPTH_COMPONENT32F TEXTURE_2D_ARRAY, LINEAR, CLAMP_TO_EDGE, COMPARE_REF_TO_TEXTURE LESS',
          meshes: meshes.length,
          renderList: renderList.length,
        },
        camera: camInfo,
      },
    };
    scene.dispose();
    return result;
  } finally {
    engine.dispose();
  }
}

window.shadowtuneRender = render;
window.shadowtuneBabylonVersion = VERSION;
