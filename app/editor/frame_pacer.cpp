#include "app/editor/frame_pacer.h"

namespace st::app {

FramePacer::Wait FramePacer::after(const FrameActivity& frame) {
    if (frame.events || frame.changed || frame.animating) settle_ = kSettleFrames;
    else if (settle_ > 0) --settle_;
    idle_ = false;
    if (settle_ > 0) return Wait::None;
    if (frame.jobRunning) return Wait::Timeout;
    idle_ = true;
    return Wait::Event;
}

}  // namespace st::app
