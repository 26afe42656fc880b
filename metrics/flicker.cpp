#include "metrics/flicker.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace st::metrics {

double FlickerMeter::Moments::stdDev(int n) const {
    if (n <= 0) return 0.0;
    const double mean = sum / n;
    return std::sqrt(std::max(sumSquares / n - mean * mean, 0.0));
}

FlickerMeter::FlickerMeter(const MeasureSamples& first, std::vector<std::uint8_t> truth, float directLight)
    : points_(first.size(), 0), hard_(first.size()), filtered_(first.size()), flipped_(first.size(), 0),
      truth_(std::move(truth)), lightOf_(first.size(), 0.0f), luminance_(first.size(), 0.0),
      lastStep_(first.size(), 0), alternated_(first.size(), 0) {
    if (!truth_.empty() && truth_.size() != first.size()) throw std::invalid_argument("flicker: truth differs in size");
    for (std::size_t i = 0; i < first.size(); ++i) {
        points_[i] = first.receiver(i);
        pointCount_ += points_[i];
        if (points_[i]) lightOf_[i] = directLight * first.normal[i].w;
    }
}

void FlickerMeter::addLuminance(std::size_t i, float filtered) {
    const double luminance = double(lightOf_[i]) * double(filtered);
    if (frames_ > 0) {
        const double change = luminance - luminance_[i];
        const std::int8_t step = std::abs(change) < kAlternationStep ? 0 : (change > 0.0 ? 1 : -1);
        // Two steps in a row of opposite sign: up and down again (or down and up) over 3 frames.
        if (step != 0 && lastStep_[i] == -step) alternated_[i] = 1;
        lastStep_[i] = step;
    }
    luminance_[i] = luminance;
}

void FlickerMeter::add(const std::vector<glm::vec4>& shadow) {
    if (shadow.size() != points_.size()) throw std::invalid_argument("flicker: frames differ in size");
    std::size_t flips = 0, wrong = 0;
    for (std::size_t i = 0; i < points_.size(); ++i) {
        if (!points_[i]) continue;
        const float hard = shadow[i].x;
        hard_[i].add(hard);
        filtered_[i].add(shadow[i].y);
        addLuminance(i, shadow[i].y);
        if (!truth_.empty()) wrong += (hard >= 0.5f) != (truth_[i] != 0);
        if (frames_ > 0 && hard != previous_[i]) {
            ++flips;
            flipped_[i] = 1;
        }
    }
    if (frames_ > 0) flipShares_.push_back(shareOfPoints(flips));
    if (!truth_.empty()) misclassified_.push_back(shareOfPoints(wrong));
    previous_.resize(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) previous_[i] = shadow[i].x;
    ++frames_;
}

double FlickerMeter::shareOfPoints(std::size_t count) const {
    return pointCount_ ? double(count) / double(pointCount_) : 0.0;
}

std::vector<float> FlickerMeter::hardStdDev() const {
    std::vector<float> out(points_.size(), 0.0f);
    for (std::size_t i = 0; i < out.size(); ++i)
        if (points_[i]) out[i] = float(hard_[i].stdDev(frames_));
    return out;
}

FlickerReport FlickerMeter::report() const {
    FlickerReport r;
    r.frames = frames_;
    r.samplePoints = pointCount_;
    r.flipShareByFrame = flipShares_;
    r.misclassifiedByFrame = misclassified_;
    r.alternatingPixels = std::size_t(std::count(alternated_.begin(), alternated_.end(), std::uint8_t(1)));
    if (!flipShares_.empty()) {
        r.flipRate = std::accumulate(flipShares_.begin(), flipShares_.end(), 0.0) / double(flipShares_.size());
        r.maxFlipShare = *std::max_element(flipShares_.begin(), flipShares_.end());
    }
    if (pointCount_ == 0) return r;
    double hardSum = 0.0, filteredSum = 0.0;
    std::size_t flickering = 0;
    for (std::size_t i = 0; i < points_.size(); ++i) {
        if (!points_[i]) continue;
        const double sd = hard_[i].stdDev(frames_);
        hardSum += sd;
        r.maxHardStdDev = std::max(r.maxHardStdDev, sd);
        filteredSum += filtered_[i].stdDev(frames_);
        flickering += flipped_[i];
    }
    r.meanHardStdDev = hardSum / double(pointCount_);
    r.meanFilteredStdDev = filteredSum / double(pointCount_);
    r.flickeringShare = double(flickering) / double(pointCount_);
    return r;
}

}  // namespace st::metrics
