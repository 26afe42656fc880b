#pragma once
// Runs a function over the rows of an image on every core. Rows are handed out one at a time
// from a shared counter, so a costly band of rows (a dense caster) does not idle the other cores.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace st::metrics {

template <class RowFn>
void forEachRowParallel(int rows, RowFn&& fn) {
    std::atomic<int> next{0};
    auto worker = [&] {
        for (int y = next++; y < rows; y = next++) fn(y);
    };
    const unsigned count = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::jthread> threads;
    for (unsigned i = 1; i < count; ++i) threads.emplace_back(worker);
    worker();
}

}  // namespace st::metrics
