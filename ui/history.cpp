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

float History::max() const {
    if (values_.empty()) return 0.0f;
    return *std::max_element(values_.begin(), values_.end());
}

}  // namespace st::ui
