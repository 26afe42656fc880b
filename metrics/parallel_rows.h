#pragma once
// Runs a function over the rows of an image on every core. Rows are handed out one at a time
// from a shared counter, so a costly band of rows (a dense caster) does not idle the other cores.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace st::metrics {

// What a caller off the UI thread needs from a row loop (the editor's Accuracy panel): a way to
// stop it early, a count to show progress with, and fewer threads than cores so the thread that
// draws the window keeps a core. The defaults: run every row on every core.
struct RowControl {
    const std::atomic<bool>* cancel = nullptr;  // once true, no further row starts
    std::atomic<int>* rowsDone = nullptr;       // incremented after each row
    unsigned threads = 0;                       // 0: one per core

    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
};

// Returns true if every row ran (false only when control.cancel stopped the loop).
template <class RowFn>
bool forEachRowParallel(int rows, RowFn&& fn, const RowControl& control = {}) {
    std::atomic<int> next{0};
    std::atomic<int> ran{0};
    auto worker = [&] {
        for (int y = next++; y < rows && !control.cancelled(); y = next++) {
            fn(y);
            ++ran;
            if (control.rowsDone) ++*control.rowsDone;
        }
    };
    const unsigned count = control.threads ? control.threads : std::max(1u, std::thread::hardware_concurrency());
    {
        std::vector<std::jthread> threads;
        for (unsigned i = 1; i < count; ++i) threads.emplace_back(worker);
        worker();
    }  // joined here
    return ran.load() == std::max(rows, 0);
}

}  // namespace st::metrics
