// Weights shared by the screen-space path's passes (renderer/render/screen_shadow.h). The mask's
// y is the view depth in metres (the clip w of a perspective camera), 0 where no surface is.
// Depth-aware (cross-bilateral) weight: a Gaussian of the depth difference relative to the
// reference depth, so the same sigma holds near and far; sigma 0 turns it off.
float screenDepthWeight(float z, float zRef) {
    if (screenDepthSigma <= 0.0) return 1.0;
    float d = (z - zRef) / (screenDepthSigma * zRef);
    return exp(-0.5 * d * d);
}

// The uploaded 1-D Gaussian weight of tap k (|k| <= screenRadius).
float screenTapWeight(int k) {
    int a = abs(k);
    return screenWeights[a / 4][a % 4];
}
