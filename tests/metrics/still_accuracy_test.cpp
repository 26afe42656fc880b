// The editor's background accuracy job without GL: it must score exactly what the direct metrics
// score, stop when cancelled and hand over nothing then, and the worker must only ever deliver
// the last frame submitted.
#include "metrics/accuracy_worker.h"
#include "metrics/resolution_check.h"
#include "metrics/still_accuracy.h"
#include "renderer/csm/cascade_plan.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

namespace st::metrics {
namespace {

const glm::vec3 kEye(0.0f, 6.0f, 12.0f);

// A floor of width x height samples spread over x, z in [-6, 6) around box-over-plane's box
// (-1,2,-1)..(1,4,1): the map says lit everywhere except a false-shadow band in the open, so the
// job finds false light under the box and false shadow in the band.
StillFrame boxFrame(std::shared_ptr<const Scene> scene, int width, int height) {
    StillFrame f;
    f.scene = std::move(scene);
    f.samples = test::floorSamples(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            f.samples.position[std::size_t(y) * width + x] =
                glm::vec4(-6.0f + 12.0f * float(x) / float(width), 0.0f, -6.0f + 12.0f * float(y) / float(height), 1.0f);
    for (int x = 0; x < width / 4; ++x) test::setMap(f.samples, x, height - 2, 0.0f, 0.25f);
    Settings s;
    s.light.elevation = 80.0f;
    s.camera.position = kEye;
    s.cascades.count = 1;
    f.plan = csm::planCascades(s, 16.0f / 9.0f, f.scene->wsBounds);
    f.mapSize = s.cascades.mapSize;
    f.cascadeCount = 1;
    f.wsEye = kEye;
    return f;
}

std::shared_ptr<const Scene> boxScene() { return std::make_shared<const Scene>(makeBuiltinScene("box-over-plane")); }

// What MeasureSession's measureStill does with the same inputs.
AccuracyReport direct(const StillFrame& f) {
    const GroundTruth truth(*f.scene);
    const std::vector<std::uint8_t> lit = truth.trace(f.samples, -f.plan.wsLightDir, f.wsEye);
    const ResolutionCheck check(truth, f.plan, f.mapSize, f.wsEye);
    return scoreAccuracy(f.samples, lit, f.cascadeCount, [&](std::size_t i, bool mapLit) {
        return check.explains(glm::vec3(f.samples.position[i]), glm::vec3(f.samples.geometry[i]), f.samples.cascade(i),
                              mapLit);
    });
}

void expectSameCounts(const ErrorCounts& a, const ErrorCounts& b) {
    EXPECT_EQ(a.receivers, b.receivers);
    EXPECT_EQ(a.falseShadowEdge, b.falseShadowEdge);
    EXPECT_EQ(a.falseShadowGross, b.falseShadowGross);
    EXPECT_EQ(a.falseLightEdge, b.falseLightEdge);
    EXPECT_EQ(a.falseLightGross, b.falseLightGross);
    EXPECT_DOUBLE_EQ(a.filteredAbsErrorSum, b.filteredAbsErrorSum);
}

std::optional<AccuracyOutcome> waitForOutcome(AccuracyWorker& w, std::chrono::seconds limit = std::chrono::seconds(60)) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
        if (auto out = w.take()) return out;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return std::nullopt;
}

TEST(ParallelRowsTest, CancelStopsHandingOutRows) {
    std::atomic<bool> cancel{false};
    std::atomic<int> done{0};
    std::vector<int> ran;
    const bool complete = forEachRowParallel(100, [&](int y) {
        ran.push_back(y);
        if (y == 3) cancel = true;
    }, RowControl{&cancel, &done, 1});
    EXPECT_FALSE(complete);
    EXPECT_EQ(ran, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(done.load(), 4);
    EXPECT_TRUE(forEachRowParallel(5, [](int) {}, RowControl{nullptr, &done, 2}));
    EXPECT_EQ(done.load(), 9);
}

TEST(StillAccuracyTest, MatchesTheDirectComputation) {
    const StillFrame f = boxFrame(boxScene(), 48, 48);
    GroundTruthCache cache;
    JobControl control;
    const std::optional<StillAccuracy> job = computeStillAccuracy(f, cache, control);
    ASSERT_TRUE(job);
    const AccuracyReport want = direct(f);
    EXPECT_EQ(job->report.classes, want.classes);
    expectSameCounts(job->report.all, want.all);
    ASSERT_EQ(job->report.cascades.size(), 1u);
    expectSameCounts(job->report.cascades[0], want.cascades[0]);
    EXPECT_GT(want.all.falseLight(), 10u);  // the box's shadow, which the map missed
    EXPECT_GT(want.all.falseShadow(), 5u);  // the band
    EXPECT_EQ(control.rowsDone.load(), 4 * 48);  // traced, traced twice over the sun's disc, scored
    EXPECT_EQ(job->soft.all.receivers, want.all.receivers);
    EXPECT_GT(job->soft.all.missingCaster + job->soft.all.edge, 10u);  // the missed shadow, against the disc too
    EXPECT_GT(job->bvhMs, 0.0);
}

bool grossAround(const AccuracyReport& r, int width, int height, std::size_t i) {
    const int x = int(i % std::size_t(width)), y = int(i / std::size_t(width));
    for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height - 1); ++ny)
        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
            const PixelClass c = r.classes[std::size_t(ny) * std::size_t(width) + std::size_t(nx)];
            if (c == PixelClass::FalseShadowGross || c == PixelClass::FalseLightGross) return true;
        }
    return false;
}

TEST(StillAccuracyTest, OverlayShowsOnlyErrorsInTwoColours) {
    const StillFrame f = boxFrame(boxScene(), 48, 48);
    GroundTruthCache cache;
    JobControl control;
    const std::optional<StillAccuracy> job = computeStillAccuracy(f, cache, control);
    ASSERT_TRUE(job);
    ASSERT_EQ(job->overlay.width, 48);
    ASSERT_EQ(job->overlay.height, 48);
    for (std::size_t i = 0; i < job->report.classes.size(); ++i) {
        const PixelClass c = job->report.classes[i];
        const std::uint8_t* p = &job->overlay.pixels[4 * i];
        const bool falseShadow = c == PixelClass::FalseShadowEdge || c == PixelClass::FalseShadowGross;
        const bool falseLight = c == PixelClass::FalseLightEdge || c == PixelClass::FalseLightGross;
        if (falseShadow) {
            EXPECT_TRUE(p[3] == 255 && p[0] > p[2]) << i;  // reds
        } else if (falseLight) {
            EXPECT_TRUE(p[3] == 255 && p[2] > p[0]) << i;  // blues
        } else if (grossAround(job->report, 48, 48, i)) {
            EXPECT_LT(p[3], 255) << i;  // the translucent ring around a gross error
        } else {
            EXPECT_EQ(p[3], 0) << i;
        }
    }
}

TEST(StillAccuracyTest, CancelledBeforeStartReturnsNothingAndBuildsNothing) {
    const StillFrame f = boxFrame(boxScene(), 16, 16);
    GroundTruthCache cache;
    JobControl control;
    control.cancel = true;
    EXPECT_FALSE(computeStillAccuracy(f, cache, control));
    EXPECT_EQ(control.rowsDone.load(), 0);
    bool built = false;
    cache.get(f.scene, &built);
    EXPECT_TRUE(built);  // the cancelled job did not build it
}

TEST(StillAccuracyTest, CancelledWhileCastingStopsEarlyAndReturnsNothing) {
    // 1.6 M rays on one thread: seconds of work, so the cancel below lands mid-job even when this
    // thread is descheduled for a while right after the first row (a loaded 2-core machine).
    constexpr int kRows = 4000;
    const StillFrame f = boxFrame(boxScene(), 400, kRows);
    GroundTruthCache cache;
    JobControl control;
    control.threads = 1;
    std::optional<StillAccuracy> result;
    std::jthread job([&] { result = computeStillAccuracy(f, cache, control); });
    while (control.rowsDone.load() == 0) std::this_thread::yield();
    control.cancel = true;
    job.join();
    EXPECT_FALSE(result);
    EXPECT_LT(control.rowsDone.load(), kRows);  // the rays stopped at a row
}

TEST(StillAccuracyTest, CacheBuildsTheBvhOncePerScene) {
    GroundTruthCache cache;
    const auto a = boxScene(), b = boxScene();
    bool built = false;
    cache.get(a, &built);
    EXPECT_TRUE(built);
    cache.get(a, &built);
    EXPECT_FALSE(built);
    cache.get(b, &built);
    EXPECT_TRUE(built);
}

TEST(AccuracyWorkerTest, DeliversTheLastFrameSubmittedOnly) {
    const auto scene = boxScene();
    StillFrame first = boxFrame(scene, 200, 400);
    StillFrame last = boxFrame(scene, 48, 48);
    const AccuracyReport want = direct(last);
    AccuracyWorker worker(1);
    EXPECT_EQ(worker.submit(std::move(first)), 1u);
    EXPECT_EQ(worker.submit(std::move(last)), 2u);
    EXPECT_TRUE(worker.progress().busy);
    const std::optional<AccuracyOutcome> out = waitForOutcome(worker);
    ASSERT_TRUE(out);
    EXPECT_EQ(out->job, 2u);
    ASSERT_TRUE(out->result) << out->error;
    EXPECT_EQ(out->result->report.classes, want.classes);
    EXPECT_FALSE(worker.progress().busy);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_FALSE(worker.take());  // the first frame's result never arrives, and nothing twice
}

// Issue 13 #10: the rays must not starve the thread drawing the window.
TEST(AccuracyWorkerTest, RunsBelowTheCallersPriority) {
    const auto tid = [] { return static_cast<id_t>(syscall(SYS_gettid)); };
    const int callerNice = getpriority(PRIO_PROCESS, tid());
    std::atomic<int> workerNice{-100};
    std::atomic<int> rowNice{-100};
    {
        AccuracyWorker worker(1, [&](const JobControl&, bool) { workerNice = getpriority(PRIO_PROCESS, tid()); });
        worker.submit(boxFrame(boxScene(), 16, 16));
        ASSERT_TRUE(waitForOutcome(worker));
    }
    EXPECT_EQ(workerNice.load(), std::min(19, callerNice + AccuracyWorker::kNiceIncrement));
    EXPECT_EQ(getpriority(PRIO_PROCESS, tid()), callerNice) << "the caller's own priority is untouched";
    // A thread the worker starts for its rows inherits the value (Linux nice values are per thread).
    std::thread([&] {
        setpriority(PRIO_PROCESS, tid(), workerNice);
        forEachRowParallel(4, [&](int) { rowNice = getpriority(PRIO_PROCESS, tid()); }, RowControl{nullptr, nullptr, 2});
    }).join();
    EXPECT_EQ(rowNice.load(), workerNice.load());
}

TEST(AccuracyWorkerTest, CancelledJobIsNeverHandedOver) {
    const auto scene = boxScene();
    AccuracyWorker worker(1);
    worker.submit(boxFrame(scene, 200, 400));
    worker.cancel();
    EXPECT_FALSE(worker.progress().busy);
    EXPECT_FALSE(waitForOutcome(worker, std::chrono::seconds(1)));
    worker.submit(boxFrame(scene, 16, 16));  // the worker is still there for the next frame
    const std::optional<AccuracyOutcome> out = waitForOutcome(worker);
    ASSERT_TRUE(out);
    EXPECT_EQ(out->job, 2u);
    EXPECT_TRUE(out->result);
}

// The editor closing mid-job: the destructor must cancel the running job and join, not wait for
// it to finish (nor hang or crash).
TEST(AccuracyWorkerTest, DestructorCancelsAndJoinsARunningJob) {
    StillFrame frame = boxFrame(boxScene(), 400, 1000);  // 0.4 M rays on one thread: seconds
    const int rows = 4 * frame.samples.height;            // traced, over the disc twice, then scored
    struct Ending {
        int count = 0;
        bool cancelled = false;
        bool completed = false;
        int rowsDone = 0;
    };
    std::mutex mutex;
    Ending ending;
    {
        AccuracyWorker worker(1, [&](const JobControl& control, bool completed) {
            std::lock_guard lock(mutex);
            ending = {ending.count + 1, control.cancelled(), completed, control.rowsDone.load()};
        });
        worker.submit(std::move(frame));
        AccuracyProgress p = worker.progress();
        for (; p.busy && p.fraction == 0.0f; p = worker.progress()) std::this_thread::yield();
        ASSERT_TRUE(p.busy) << "the job ended before it was seen running";
    }  // ~AccuracyWorker: cancel, join
    std::lock_guard lock(mutex);
    EXPECT_EQ(ending.count, 1);  // the job ended before the destructor returned
    EXPECT_TRUE(ending.cancelled);
    EXPECT_FALSE(ending.completed);
    EXPECT_GT(ending.rowsDone, 0);     // it was running ...
    EXPECT_LT(ending.rowsDone, rows);  // ... and stopped early
}

}  // namespace
}  // namespace st::metrics
