#include "app/editor/accuracy_schedule.h"

namespace st::app {

AccuracySchedule::Action AccuracySchedule::update(double now, bool changed) {
    if (changed || !haveFrame_) {
        const bool wasComputing = state_ == State::Computing;
        state_ = State::Settling;
        haveFrame_ = true;
        stillSince_ = now;
        return wasComputing ? Action::Cancel : Action::None;
    }
    if (state_ != State::Settling || now - stillSince_ < settleSeconds_) return Action::None;
    state_ = State::Computing;
    return Action::Start;
}

void AccuracySchedule::finished(bool ok) {
    if (state_ == State::Computing) state_ = ok ? State::Done : State::Failed;
}

}  // namespace st::app
