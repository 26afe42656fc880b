// UndoStack: snapshots in, snapshots out; no ImGui, no GL.
#include "ui/undo_stack.h"

#include <gtest/gtest.h>

using st::Settings;
using st::ui::UndoStack;

namespace {
Settings withLambda(float lambda) {
    Settings s;
    s.cascades.lambda = lambda;
    return s;
}
}  // namespace

TEST(UndoStackTest, StartsEmpty) {
    UndoStack stack;
    EXPECT_FALSE(stack.canUndo());
    EXPECT_FALSE(stack.canRedo());
    EXPECT_FALSE(stack.undo(Settings{}));
    EXPECT_FALSE(stack.redo(Settings{}));
}

TEST(UndoStackTest, UndoRestoresTheStateBeforeAnEditAndRedoTheStateAfter) {
    UndoStack stack;
    ASSERT_TRUE(stack.push(withLambda(0.5f), withLambda(0.8f)));
    const auto undone = stack.undo(withLambda(0.8f));
    ASSERT_TRUE(undone);
    EXPECT_EQ(undone->cascades.lambda, 0.5f);
    EXPECT_TRUE(stack.canRedo());
    const auto redone = stack.redo(*undone);
    ASSERT_TRUE(redone);
    EXPECT_EQ(redone->cascades.lambda, 0.8f);
    EXPECT_FALSE(stack.canRedo());
    EXPECT_TRUE(stack.canUndo());
}

TEST(UndoStackTest, StepsBackThroughSeveralEditsInOrder) {
    UndoStack stack;
    stack.push(withLambda(0.1f), withLambda(0.2f));
    stack.push(withLambda(0.2f), withLambda(0.3f));
    stack.push(withLambda(0.3f), withLambda(0.4f));
    Settings current = withLambda(0.4f);
    for (const float expected : {0.3f, 0.2f, 0.1f}) {
        current = *stack.undo(current);
        EXPECT_EQ(current.cascades.lambda, expected);
    }
    EXPECT_FALSE(stack.canUndo());
    EXPECT_EQ(stack.redoCount(), 3u);
}

TEST(UndoStackTest, AnEditWithoutChangeIsNotRecorded) {
    UndoStack stack;
    EXPECT_FALSE(stack.push(withLambda(0.5f), withLambda(0.5f)));  // a drag back to where it started
    EXPECT_FALSE(stack.canUndo());
}

TEST(UndoStackTest, ANewEditClearsRedo) {
    UndoStack stack;
    stack.push(withLambda(0.1f), withLambda(0.2f));
    const Settings undone = *stack.undo(withLambda(0.2f));
    ASSERT_TRUE(stack.canRedo());
    stack.push(undone, withLambda(0.9f));
    EXPECT_FALSE(stack.canRedo());
}

TEST(UndoStackTest, DropsTheOldestEntriesBeyondCapacity) {
    UndoStack stack(2);
    stack.push(withLambda(0.1f), withLambda(0.2f));
    stack.push(withLambda(0.2f), withLambda(0.3f));
    stack.push(withLambda(0.3f), withLambda(0.4f));
    EXPECT_EQ(stack.undoCount(), 2u);
    Settings current = *stack.undo(withLambda(0.4f));
    current = *stack.undo(current);
    EXPECT_EQ(current.cascades.lambda, 0.2f);
    EXPECT_FALSE(stack.canUndo());
}

TEST(UndoStackTest, ClearForgetsBothDirections) {
    UndoStack stack;
    stack.push(withLambda(0.1f), withLambda(0.2f));
    stack.push(withLambda(0.2f), withLambda(0.3f));
    stack.undo(withLambda(0.3f));
    stack.clear();
    EXPECT_FALSE(stack.canUndo());
    EXPECT_FALSE(stack.canRedo());
}
