#pragma once
// A debug EGL context per test binary; any medium/high KHR_debug message fails the test.
#include "renderer/context/egl_context.h"
#include "renderer/gpu/debug_output.h"

#include <gtest/gtest.h>

#include <memory>

namespace st::test {

class GLTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!context_) {
            context_ = HeadlessContext::create(true);
            gpu::enableDebugOutput();
        }
    }
    void SetUp() override { messagesBefore_ = gpu::seriousDebugMessageCount(); }
    void TearDown() override {
        EXPECT_EQ(gpu::seriousDebugMessageCount(), messagesBefore_) << "GL debug output reported errors";
    }

    // For a test that provokes exactly `count` serious messages on purpose (a broken shader):
    // fails unless that many arrived since the last check, then expects none more.
    void expectDebugMessages(int count) {
        EXPECT_EQ(gpu::seriousDebugMessageCount() - messagesBefore_, count) << "serious GL debug messages";
        messagesBefore_ = gpu::seriousDebugMessageCount();
    }

private:
    static inline std::unique_ptr<HeadlessContext> context_;
    int messagesBefore_ = 0;
};

}  // namespace st::test
