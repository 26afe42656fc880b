#include "app/editor/frame_times.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace st::app {
namespace {
double medianAfterFirst(const std::vector<double>& v) {
    std::vector<double> t(v.begin() + 1, v.end());
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}
}  // namespace

void FrameTimes::print() const {
    if (frameMs_.size() < 3) return;
    const double median = medianAfterFirst(frameMs_);
    std::printf("%zu frames, median frame %.1f ms (%.1f fps), process CPU %.1f ms a frame\n", frameMs_.size() - 1,
                median, 1000.0 / median, medianAfterFirst(frameCpuMs_));
    // The UI's frame rate and the scene's render time differ once frames reuse the image.
    if (sceneMs_.size() < 2) {
        std::printf("scene rendered %zu times, reused %d times\n", sceneMs_.size(), reused_);
        return;
    }
    std::printf("scene rendered %zu times (median %.1f ms, median scale %.0f %%), reused %d times\n", sceneMs_.size(),
                medianAfterFirst(sceneMs_), 100.0 * medianAfterFirst(sceneScales_), reused_);
}

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

}  // namespace st::app
