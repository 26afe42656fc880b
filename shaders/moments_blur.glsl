// The 1-D Gaussian of the moment blur: taps -r..r, sigma = (r + 1) / 2 texels, normalised so the
// taps sum to 1. The CPU uploads the weights (renderer/csm/filter_weights.h, blurWeights): one
// fetch per tap, where computing them here cost O(r) exp() per tap.
float blurWeight(int k) {
    int a = abs(k);
    return blurWeights[a / 4][a % 4];
}
