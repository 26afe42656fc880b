// A rasterizer with fewer sub-pixel bits than this one snaps each vertex to a coarser grid before
// it draws and sets up its interpolation from the snapped positions: SwiftShader as Chromium ships
// it keeps 4 bits (1/16 pixel; WebGL's SUBPIXEL_BITS; src/Pipeline/SetupRoutine.cpp rounds
// (x_window - 0.5) * 16 to nearest even), Mesa's llvmpipe 8. Snapping here first reproduces the
// coarser grid: a multiple of 1/16 pixel is one of 1/256 too, which this rasterizer leaves in place.
// Vertices behind the eye (w < 0) are snapped through their projection as well, as SwiftShader does
// for the triangle's interpolation planes; w == 0 has no projection and is left alone.
vec4 snapToSubpixels(vec4 clip) {
    if (subpixelSteps <= 0 || clip.w == 0.0) return clip;
    vec2 size = vec2(viewportWidth, viewportHeight);
    float steps = float(subpixelSteps);
    vec2 window = (clip.xy / clip.w * 0.5 + 0.5) * size;
    window = roundEven(window * steps) / steps;
    return vec4(((window / size) * 2.0 - 1.0) * clip.w, clip.zw);
}
