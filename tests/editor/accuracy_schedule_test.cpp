// When the editor's Accuracy panel computes: made-up frame times and change events in, actions
// out. No window, no threads, no clock.
#include "app/editor/accuracy_schedule.h"

#include <gtest/gtest.h>

using namespace st::app;
using Action = AccuracySchedule::Action;
using State = AccuracySchedule::State;

namespace {

// Still frames every 1/60 s from `from` until an action other than None, or `until`.
Action runStill(AccuracySchedule& s, double from, double until, double* at = nullptr) {
    for (double t = from; t <= until; t += 1.0 / 60.0) {
        const Action a = s.update(t, false);
        if (a != Action::None) {
            if (at) *at = t;
            return a;
        }
    }
    return Action::None;
}

}  // namespace

TEST(AccuracyScheduleTest, StartsOnceTheFrameHasBeenStillForTheSettleTime) {
    AccuracySchedule s(0.4);
    EXPECT_EQ(s.update(10.0, false), Action::None);  // the first frame starts the clock
    EXPECT_EQ(s.state(), State::Settling);
    EXPECT_EQ(s.update(10.39, false), Action::None);
    EXPECT_EQ(s.update(10.4, false), Action::Start);
    EXPECT_EQ(s.state(), State::Computing);
    EXPECT_EQ(s.update(10.5, false), Action::None);  // one job per still frame
    EXPECT_EQ(s.update(99.0, false), Action::None);
}

TEST(AccuracyScheduleTest, ContinuousChangesNeverStartAJob) {
    AccuracySchedule s(0.4);
    for (double t = 0.0; t < 10.0; t += 0.1) EXPECT_EQ(s.update(t, true), Action::None) << t;
    EXPECT_EQ(s.state(), State::Settling);
}

TEST(AccuracyScheduleTest, AChangeWhileComputingCancelsAndRestartsTheClock) {
    AccuracySchedule s(0.4);
    double started = 0.0;
    ASSERT_EQ(runStill(s, 0.0, 1.0, &started), Action::Start);
    EXPECT_EQ(s.update(started + 0.5, true), Action::Cancel);
    EXPECT_EQ(s.state(), State::Settling);
    EXPECT_EQ(s.update(started + 0.6, true), Action::None);  // nothing left to cancel
    double restarted = 0.0;
    ASSERT_EQ(runStill(s, started + 0.61, started + 2.0, &restarted), Action::Start);
    EXPECT_NEAR(restarted, started + 0.6 + 0.4, 1.0 / 60.0 + 1e-9);  // from the last change
}

TEST(AccuracyScheduleTest, ResultOfACancelledJobDoesNotCount) {
    AccuracySchedule s(0.4);
    ASSERT_EQ(runStill(s, 0.0, 1.0), Action::Start);
    ASSERT_EQ(s.update(1.1, true), Action::Cancel);
    s.finished(true);  // a stale job ending anyway must not show figures for the new frame
    EXPECT_EQ(s.state(), State::Settling);
}

TEST(AccuracyScheduleTest, DoneStaysUntilAChangeAndDoesNotRecompute) {
    AccuracySchedule s(0.4);
    ASSERT_EQ(runStill(s, 0.0, 1.0), Action::Start);
    s.finished(true);
    EXPECT_EQ(s.state(), State::Done);
    EXPECT_EQ(runStill(s, 1.0, 5.0), Action::None);
    EXPECT_EQ(s.state(), State::Done);
    EXPECT_EQ(s.update(5.1, true), Action::None);  // figures dropped, no job to cancel
    EXPECT_EQ(s.state(), State::Settling);
    EXPECT_EQ(runStill(s, 5.2, 6.0), Action::Start);
}

TEST(AccuracyScheduleTest, FailureIsNotRetriedUntilTheFrameChanges) {
    AccuracySchedule s(0.4);
    ASSERT_EQ(runStill(s, 0.0, 1.0), Action::Start);
    s.finished(false);
    EXPECT_EQ(s.state(), State::Failed);
    EXPECT_EQ(runStill(s, 1.0, 5.0), Action::None);
    s.update(5.1, true);
    EXPECT_EQ(runStill(s, 5.2, 6.0), Action::Start);
}
