// Issue 21 #2: the editor draws while something happens and waits for an event otherwise.
#include "app/editor/frame_pacer.h"

#include <gtest/gtest.h>

using namespace st::app;
using Wait = FramePacer::Wait;

namespace {
// Frames with nothing happening until the pacer waits; returns how many it drew at once.
int framesUntilWait(FramePacer& pacer, const FrameActivity& quiet = {}) {
    for (int n = 1; n < 100; ++n)
        if (pacer.after(quiet) != Wait::None) return n;
    return 100;
}
}  // namespace

TEST(FramePacerTest, AQuietEditorWaitsForAnEventAfterTheSettlingFrames) {
    FramePacer pacer;
    EXPECT_EQ(framesUntilWait(pacer), FramePacer::kSettleFrames) << "the first frames place the panels";
    EXPECT_TRUE(pacer.idle());
    EXPECT_EQ(pacer.after({}), Wait::Event) << "and it stays waiting";
}

TEST(FramePacerTest, AnEventOrAChangeDrawsTheSettlingFramesAgain) {
    FramePacer pacer;
    framesUntilWait(pacer);
    EXPECT_EQ(pacer.after({.events = true}), Wait::None);
    EXPECT_FALSE(pacer.idle());
    EXPECT_EQ(framesUntilWait(pacer), FramePacer::kSettleFrames);
    EXPECT_EQ(pacer.after({.changed = true}), Wait::None) << "e.g. the full frame after a move";
    EXPECT_EQ(framesUntilWait(pacer), FramePacer::kSettleFrames);
}

TEST(FramePacerTest, AnimationDrawsEveryFrame) {
    FramePacer pacer;
    framesUntilWait(pacer);
    for (int i = 0; i < 50; ++i) EXPECT_EQ(pacer.after({.animating = true}), Wait::None);
    EXPECT_EQ(framesUntilWait(pacer), FramePacer::kSettleFrames) << "then it settles as after a change";
}

TEST(FramePacerTest, ARunningJobIsPolledWithATimeoutNeverWaitedOnForever) {
    FramePacer pacer;
    const FrameActivity job{.jobRunning = true};
    EXPECT_EQ(framesUntilWait(pacer, job), FramePacer::kSettleFrames);
    EXPECT_EQ(pacer.after(job), Wait::Timeout);
    EXPECT_FALSE(pacer.idle()) << "a job runs: not idle";
    EXPECT_EQ(pacer.after({}), Wait::Event) << "the job ended";
    EXPECT_TRUE(pacer.idle());
}
