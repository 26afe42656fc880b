#version 450 core
// Depth only, for materials without an alpha mask: llvmpipe skips an empty fragment shader's
// work, so such casters rasterise about three times as fast as through shadow_depth.frag.
void main() {}
