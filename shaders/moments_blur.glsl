// The 1-D Gaussian of the moment blur: taps -r..r, sigma = (r + 1) / 2 texels (the rule of the
// Gaussian PCF weights, renderer/csm/filter_weights.h), normalised so the taps sum to 1.
float blurWeight(int k, int r) {
    float sigma = 0.5 * float(r + 1);
    float sum = 0.0;
    for (int j = -r; j <= r; ++j) sum += exp(-float(j * j) / (2.0 * sigma * sigma));
    return exp(-float(k * k) / (2.0 * sigma * sigma)) / sum;
}
