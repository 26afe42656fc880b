// Step 6 of seed 001: with the screen-space path on (ViewBlock::screenShadow) a pass reads the
// factor from the upsampled mask under its pixel instead of filtering the maps, and selects the
// cascade only for the views that show it. The mask was drawn with this pass's camera and size.
// Include after shadow_sampling.glsl.
layout(binding = ST_BINDING_SCREEN_SHADOW) uniform sampler2D uScreenShadow;

ShadowResult screenShadowFactor(vec3 wsPos, vec3 wsNormal, float vsDepth) {
    int c = selection == ST_SELECT_INTERVAL ? selectInterval(vsDepth) : selectMap(wsPos, wsNormal);
    return ShadowResult(texelFetch(uScreenShadow, ivec2(gl_FragCoord.xy), 0).r, c);
}
