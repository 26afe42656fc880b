#pragma once
// One background thread for the editor's Accuracy panel. It runs computeStillAccuracy on the
// newest frame submitted and never makes the caller wait: a new frame cancels the job in flight
// (it stops at its next row) and replaces one still queued, and results of cancelled or
// superseded jobs are dropped, so take() only ever hands over figures of the last frame
// submitted. The destructor cancels and joins (waiting at most for a BVH build, which Embree
// cannot interrupt, or one row).
#include "metrics/still_accuracy.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

namespace st::metrics {

struct AccuracyOutcome {
    std::uint64_t job = 0;
    std::optional<StillAccuracy> result;  // empty: the job failed, `error` says why
    std::string error;
    double seconds = 0.0;  // from submit() to the end, waiting behind a cancelled job included
};

struct AccuracyProgress {
    bool busy = false;  // the last job submitted is queued or running
    JobControl::Phase phase = JobControl::Phase::Queued;
    float fraction = 0.0f;  // of its rows, traced and scored
};

class AccuracyWorker {
public:
    // Called on the worker thread when a job's computation ends, before its outcome is kept or
    // dropped: the job's control (cancel flag, rows done) and whether it produced figures. Lets a
    // test see that a job was stopped rather than waited for; the editor passes none.
    using JobEndObserver = std::function<void(const JobControl& control, bool completed)>;

    // Added to the worker thread's nice value (and so its ray threads'): the UI comes first.
    static constexpr int kNiceIncrement = 10;

    // rayThreads: threads the rows of a job run on (0: one per core).
    explicit AccuracyWorker(unsigned rayThreads = 0, JobEndObserver onJobEnd = {});
    ~AccuracyWorker();
    AccuracyWorker(const AccuracyWorker&) = delete;
    AccuracyWorker& operator=(const AccuracyWorker&) = delete;

    std::uint64_t submit(StillFrame frame);  // returns the job's id (increasing from 1)
    void cancel();                           // the last job's result will never be handed over
    AccuracyProgress progress() const;
    std::optional<AccuracyOutcome> take();   // the last job's outcome, once, when it has ended

private:
    using Clock = std::chrono::steady_clock;
    struct Job {
        std::uint64_t id = 0;
        StillFrame frame;
        std::shared_ptr<JobControl> control;
        Clock::time_point submitted;
    };
    void loop();
    AccuracyOutcome execute(Job& job);
    void cancelCurrentLocked();

    const unsigned rayThreads_;
    const JobEndObserver onJobEnd_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Job> pending_;
    std::shared_ptr<JobControl> current_;  // the job whose result is wanted, queued or running
    int currentRows_ = 0;                  // its rows to trace and score
    std::uint64_t lastId_ = 0;
    std::optional<AccuracyOutcome> outcome_;
    bool stop_ = false;
    GroundTruthCache cache_;  // used by the worker thread only
    std::thread thread_;      // last: starts once everything above exists
};

}  // namespace st::metrics
