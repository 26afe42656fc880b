#pragma once
// The visible clusters of a pass turned into few GL calls (issue 11 item 2): clusters are sorted
// by material and contiguous in the clustered index buffer (renderer/scene/clusters.h), so
// consecutive visible clusters merge into one index range and each material's ranges are drawn
// by one glMultiDrawElements. 100,000 small objects of one material are then a handful of
// ranges in one call, not 100,000 draws. No GL here: SceneGpu::drawBatches issues them.
#include "renderer/scene/clusters.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace st {

struct DrawBatch {
    int material = 0;
    std::vector<std::int32_t> counts;        // indices per range
    std::vector<std::uintptr_t> byteOffsets; // into the clustered index buffer
};

class DrawBatches {
public:
    void clear();
    // Appends cluster `index` of `clusters`, in any order: a cluster that starts where the last
    // range ends extends it, one of another material than the last starts a new batch.
    void add(const std::vector<Cluster>& clusters, std::size_t index);
    const std::vector<DrawBatch>& batches() const { return batches_; }
    std::size_t clusterCount() const { return clusters_; }
    std::size_t triangleCount() const { return triangles_; }
    std::size_t rangeCount() const;
    // FNV-1a 64 of the added cluster indices: equal sets give equal hashes (the cascade cache
    // compares casters by it).
    std::uint64_t hash() const { return hash_; }

private:
    std::vector<DrawBatch> batches_;
    std::size_t clusters_ = 0;
    std::size_t triangles_ = 0;
    std::uint64_t hash_ = 14695981039346656037ull;
    std::uint32_t nextIndex_ = 0;  // first index after the last range: a cluster starting here extends it
};

}  // namespace st
