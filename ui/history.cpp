#include "ui/history.h"

#include <algorithm>
#include <numeric>

namespace st::ui {

History::History(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {
    values_.reserve(capacity_);
}

void History::push(float value) {
    if (values_.size() < capacity_) {
        values_.push_back(value);
        return;
    }
    values_[next_] = value;
    next_ = (next_ + 1) % capacity_;
}

void History::clear() {
    values_.clear();
    next_ = 0;
}

float History::latest() const {
    if (values_.empty()) return 0.0f;
    if (values_.size() < capacity_) return values_.back();
    return values_[(next_ + capacity_ - 1) % capacity_];
}

float History::mean() const {
    if (values_.empty()) return 0.0f;
    return std::accumulate(values_.begin(), values_.end(), 0.0f) / static_cast<float>(values_.size());
}

float History::recentMedian(std::size_t count) const {
    const std::size_t n = std::min(count, values_.size());
    if (n == 0) return 0.0f;
    std::vector<float> recent;
    recent.reserve(n);
    // Newest first: the slot before next_ once the ring is full, else the end of the vector.
    const std::size_t newest = values_.size() < capacity_ ? values_.size() : next_;
    for (std::size_t i = 1; i <= n; ++i) recent.push_back(values_[(newest + values_.size() - i) % values_.size()]);
    std::sort(recent.begin(), recent.end());
    return n % 2 ? recent[n / 2] : 0.5f * (recent[n / 2 - 1] + recent[n / 2]);
}

float History::max() const {
    if (values_.empty()) return 0.0f;
    return *std::max_element(values_.begin(), values_.end());
}

}  // namespace st::ui
