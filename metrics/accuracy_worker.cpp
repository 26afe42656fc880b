#include "metrics/accuracy_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <exception>

namespace st::metrics {

AccuracyWorker::AccuracyWorker(unsigned rayThreads, JobEndObserver onJobEnd)
    : rayThreads_(rayThreads), onJobEnd_(std::move(onJobEnd)), thread_([this] { loop(); }) {}

AccuracyWorker::~AccuracyWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        cancelCurrentLocked();
    }
    wake_.notify_all();
    thread_.join();
}

void AccuracyWorker::cancelCurrentLocked() {
    if (current_) current_->cancel = true;
    current_.reset();
    pending_.reset();
    outcome_.reset();
}

std::uint64_t AccuracyWorker::submit(StillFrame frame) {
    Job job;
    job.frame = std::move(frame);
    job.control = std::make_shared<JobControl>();
    job.control->threads = rayThreads_;
    job.submitted = Clock::now();
    {
        std::lock_guard lock(mutex_);
        cancelCurrentLocked();
        job.id = ++lastId_;
        current_ = job.control;
        currentRows_ = 4 * job.frame.samples.height;  // JobControl's rows
        pending_ = std::move(job);
    }
    wake_.notify_all();
    return lastId_;
}

void AccuracyWorker::cancel() {
    std::lock_guard lock(mutex_);
    cancelCurrentLocked();
}

AccuracyProgress AccuracyWorker::progress() const {
    std::lock_guard lock(mutex_);
    if (!current_) return {};
    const float done = float(current_->rowsDone.load()) / float(std::max(currentRows_, 1));
    return {true, current_->phase.load(), std::min(done, 1.0f)};
}

std::optional<AccuracyOutcome> AccuracyWorker::take() {
    std::lock_guard lock(mutex_);
    return std::exchange(outcome_, std::nullopt);
}

AccuracyOutcome AccuracyWorker::execute(Job& job) {
    AccuracyOutcome out;
    out.job = job.id;
    try {
        out.result = computeStillAccuracy(job.frame, cache_, *job.control);
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    out.seconds = std::chrono::duration<double>(Clock::now() - job.submitted).count();
    if (onJobEnd_) onJobEnd_(*job.control, out.result.has_value());
    return out;
}

void AccuracyWorker::loop() {
    // Background work: on a 2-core machine the thread drawing the window must win the core it
    // shares with the rays (issue 13 #10). Linux keeps nice values per thread, and the threads
    // started from this one (the ray rows, Embree's BVH builders) inherit it.
    const auto tid = static_cast<id_t>(syscall(SYS_gettid));
    setpriority(PRIO_PROCESS, tid, std::min(19, getpriority(PRIO_PROCESS, tid) + kNiceIncrement));
    for (;;) {
        Job job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stop_ || pending_; });
            if (stop_) return;
            job = std::move(*pending_);
            pending_.reset();
        }
        AccuracyOutcome out = execute(job);
        std::lock_guard lock(mutex_);
        // A job cancelled or superseded meanwhile is no longer current_: its result is stale.
        if (job.control != current_ || job.control->cancelled()) continue;
        outcome_ = std::move(out);
        current_.reset();
    }
}

}  // namespace st::metrics
