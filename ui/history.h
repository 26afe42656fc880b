#pragma once
// Fixed-size ring buffers of per-frame timings for the plots (ImGui::PlotLines reads a ring
// directly through its values_offset argument). Pure, no ImGui.
#include <cstddef>
#include <vector>

namespace st::ui {

class History {
public:
    explicit History(std::size_t capacity);
    void push(float value);
    void clear();

    // PlotLines(values = data(), count = size(), offset = offset()) draws oldest to newest.
    const float* data() const { return values_.data(); }
    std::size_t size() const { return values_.size(); }
    std::size_t offset() const { return values_.size() < capacity_ ? 0 : next_; }
    float latest() const;  // 0 when empty
    float mean() const;    // 0 when empty
    float max() const;     // 0 when empty
    // The median of the newest `count` values (all of them when fewer); the mean of the middle
    // two for an even count. 0 when empty.
    float recentMedian(std::size_t count) const;

private:
    std::size_t capacity_;
    std::size_t next_ = 0;  // slot the next push overwrites once full
    std::vector<float> values_;
};

// The timings plotted in the editor, one History each.
struct TimingHistory {
    static constexpr std::size_t kFrames = 240;  // about four seconds at 60 Hz
    History gpuShadowMs{kFrames};
    History gpuMainMs{kFrames};
    History cpuFrameMs{kFrames};
};

}  // namespace st::ui
