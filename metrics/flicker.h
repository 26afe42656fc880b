#pragma once
// Stability (docs/architecture.md#flicker): along a camera path with a static scene and
// light, the share of fixed world-space sample points whose shadow result changes between
// consecutive frames. The observer camera stands still, so each of its pixels is one fixed world
// point; only the cascade camera moves. The ground truth never changes there, so every change
// is an artifact.
#include "renderer/render/measure_samples.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace st::metrics {

struct FlickerReport {
    int frames = 0;
    std::size_t samplePoints = 0;   // observer pixels facing the sun
    double flipRate = 0.0;          // F: mean over frame pairs of the share of points whose hard result flips
    double maxFlipShare = 0.0;      // the worst frame pair's share
    double flickeringShare = 0.0;   // share of points that flip at least once
    double meanHardStdDev = 0.0;    // per-point temporal standard deviation of the hard result, mean
    double maxHardStdDev = 0.0;
    double meanFilteredStdDev = 0.0;  // the same for the filtered factor
    // The saccade tool's unit: points whose signed luminance change alternates sign with magnitude
    // >= kAlternationStep over >= 3 consecutive frames (up then down, or down then up, by a step
    // each). Luminance: the direct term a white surface shows, intensity x N.L x filtered factor
    // (the ambient term and the surface colour do not change along the path).
    std::size_t alternatingPixels = 0;
    // Per frame pair k-1 -> k (k = 1 .. frames-1, so frames-1 entries): the share of points whose
    // hard result flips; their mean is flipRate.
    std::vector<double> flipShareByFrame;
    // Per frame (frames entries), with a truth: the share of points whose hard result (lit at
    // >= 0.5) disagrees with it, as the accuracy figures count misclassification. Empty without.
    std::vector<double> misclassifiedByFrame;
};

// Smallest luminance change (of 1 = full direct light) that counts as a step of alternation.
inline constexpr double kAlternationStep = 0.02;

class FlickerMeter {
public:
    // The sample points: the receivers of `first` (pixels with a surface facing the sun).
    // `truth` (1 lit, 0 shadowed per pixel, or empty) is the still truth of the observer's pixels,
    // the same for every frame; with it each frame's misclassified share is kept.
    // `directLight` (light.intensity) scales each point's N.L into the luminance the alternation
    // count reads.
    explicit FlickerMeter(const MeasureSamples& first, std::vector<std::uint8_t> truth = {}, float directLight = 1.0f);

    // Every frame's MeasureSamples::shadow in path order, the first frame's included.
    void add(const std::vector<glm::vec4>& shadow);
    FlickerReport report() const;
    std::vector<float> hardStdDev() const;  // per pixel (0 off the sample points)

private:
    struct Moments {
        double sum = 0.0;
        double sumSquares = 0.0;
        void add(double v) {
            sum += v;
            sumSquares += v * v;
        }
        double stdDev(int n) const;
    };

    double shareOfPoints(std::size_t count) const;
    void addLuminance(std::size_t i, float filtered);  // the alternation count's step for point i

    std::vector<std::uint8_t> points_;
    std::size_t pointCount_ = 0;
    std::vector<float> previous_;  // hard result of the last frame
    std::vector<Moments> hard_;
    std::vector<Moments> filtered_;
    std::vector<std::uint8_t> flipped_;
    std::vector<double> flipShares_;  // per consecutive pair
    std::vector<std::uint8_t> truth_;
    std::vector<double> misclassified_;  // per frame, with a truth
    std::vector<float> lightOf_;          // per point: intensity x N.L, luminance per unit of factor
    std::vector<double> luminance_;       // of the last frame
    std::vector<std::int8_t> lastStep_;   // sign of the last change if it was a step, else 0
    std::vector<std::uint8_t> alternated_;
    int frames_ = 0;
};

}  // namespace st::metrics
