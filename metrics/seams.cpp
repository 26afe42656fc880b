#include "metrics/seams.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace st::metrics {
namespace {

bool scored(const MeasureSamples& s, std::size_t i) { return s.receiver(i) && s.cascade(i) >= 0; }

double filtered(const MeasureSamples& s, std::size_t i) { return double(s.shadow[i].y); }

// Both pixels on one plane: the same triangle normal and within 1 cm of each other's plane, so a
// step from a slat to the ground behind it is not taken for a seam.
bool samePlane(const MeasureSamples& s, std::size_t i, std::size_t j) {
    const glm::vec3 n(s.geometry[i]);
    const glm::vec3 d = glm::vec3(s.position[j]) - glm::vec3(s.position[i]);
    return glm::dot(n, glm::vec3(s.geometry[j])) > 0.999f && std::abs(glm::dot(n, d)) < 0.01f;
}

// Calls pair(i, j) for every right and lower neighbour j of i where both are scored, their
// cascades differ, their truth agrees and they lie on one plane.
template <class F>
void forEachSeamPair(const MeasureSamples& s, const std::vector<std::uint8_t>& truth, F pair) {
    const auto w = std::size_t(s.width);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!scored(s, i)) continue;
        for (std::size_t j : {i + 1, i + w}) {
            const bool neighbour = j < s.size() && (j != i + 1 || (i + 1) % w != 0);
            if (neighbour && scored(s, j) && s.cascade(j) != s.cascade(i) && truth[i] == truth[j] &&
                samePlane(s, i, j))
                pair(i, j);
        }
    }
}

std::vector<std::uint8_t> seamPixels(const MeasureSamples& s, const std::vector<std::uint8_t>& truth) {
    std::vector<std::uint8_t> seam(s.size(), 0);
    forEachSeamPair(s, truth, [&](std::size_t i, std::size_t j) { seam[i] = seam[j] = 1; });
    return seam;
}

}  // namespace

std::vector<std::uint8_t> seamBand(const MeasureSamples& s, const std::vector<std::uint8_t>& truth, int radius) {
    const std::vector<std::uint8_t> seam = seamPixels(s, truth);
    std::vector<std::uint8_t> band(s.size(), 0);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            if (!seam[std::size_t(y) * std::size_t(s.width) + std::size_t(x)]) continue;
            for (int v = std::max(0, y - radius); v <= std::min(s.height - 1, y + radius); ++v)
                for (int u = std::max(0, x - radius); u <= std::min(s.width - 1, x + radius); ++u)
                    band[std::size_t(v) * std::size_t(s.width) + std::size_t(u)] = 1;
        }
    return band;
}

SeamReport measureSeams(const MeasureSamples& s, const std::vector<std::uint8_t>& truth, int radius) {
    const std::vector<std::uint8_t> band = seamBand(s, truth, radius);
    SeamReport r;
    double errorSum = 0.0, jumpSum = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!band[i] || !scored(s, i)) continue;
        ++r.bandPixels;
        errorSum += std::abs(filtered(s, i) - double(truth[i]));
    }
    forEachSeamPair(s, truth, [&](std::size_t i, std::size_t j) {
        ++r.pairs;
        jumpSum += std::abs(filtered(s, i) - filtered(s, j));
    });
    if (r.bandPixels) r.meanAbsError = errorSum / double(r.bandPixels);
    if (r.pairs) r.meanAbsJump = jumpSum / double(r.pairs);
    return r;
}

}  // namespace st::metrics
