#include "renderer/render/draw_batches.h"

namespace st {

void DrawBatches::clear() {
    batches_.clear();
    clusters_ = triangles_ = 0;
    hash_ = 14695981039346656037ull;
    nextIndex_ = 0;
}

void DrawBatches::add(const std::vector<Cluster>& clusters, std::size_t index) {
    const Cluster& k = clusters[index];
    ++clusters_;
    triangles_ += k.indexCount / 3;
    for (int byte = 0; byte < 8; ++byte) {
        hash_ ^= (std::uint64_t(index) >> (8 * byte)) & 0xffu;
        hash_ *= 1099511628211ull;
    }
    if (batches_.empty() || batches_.back().material != k.material) {
        batches_.push_back({k.material, {}, {}});
    } else if (k.firstIndex == nextIndex_) {
        batches_.back().counts.back() += std::int32_t(k.indexCount);
        nextIndex_ = k.firstIndex + k.indexCount;
        return;
    }
    batches_.back().counts.push_back(std::int32_t(k.indexCount));
    batches_.back().byteOffsets.push_back(std::uintptr_t(k.firstIndex) * sizeof(std::uint32_t));
    nextIndex_ = k.firstIndex + k.indexCount;
}

std::size_t DrawBatches::rangeCount() const {
    std::size_t n = 0;
    for (const DrawBatch& b : batches_) n += b.counts.size();
    return n;
}

}  // namespace st
