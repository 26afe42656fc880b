#pragma once
// The Accuracy panel's machinery: AccuracySchedule decides when, the measurement pass reads the
// still frame back on this (the GL) thread, metrics::AccuracyWorker builds the BVH and casts the
// rays on its own thread, and the result becomes the panel's figures and the overlay texture.
// The UI thread never waits for the worker: it polls once per frame.
#include "app/editor/accuracy_schedule.h"
#include "metrics/accuracy_worker.h"
#include "renderer/render/image_texture.h"
#include "renderer/render/measure_pass.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"
#include "ui/accuracy_view.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

class EditorAccuracy {
public:
    EditorAccuracy();  // needs the GL context current

    // Once per frame, after the scene view was rendered. `rendered`: `r` holds the frame of `s`
    // (s.output = the scene view's size; false when rendering failed or the window is too small).
    // `wanted`: the panel is open. Needs the GL context current.
    void update(double now, bool wanted, bool rendered, Renderer& r, const Settings& s,
                const std::shared_ptr<const Scene>& scene);

    ui::AccuracyView view() const;
    GLuint overlay() const;  // 0 unless the figures describe the frame of the last update()
    bool finished() const;   // the last job ended (done or failed): scripted runs wait for it
    bool done() const { return schedule_.state() == AccuracySchedule::State::Done; }
    // Figures are on their way for the frame on screen (settling or computing): the window must
    // keep polling. False once they are in, or when they are not wanted or the frame cannot be measured.
    bool busy() const;
    std::string summary() const;  // one line: state and the frame's figures
    // Per pixel of the frame measured (the hover probe's truth); nullptr unless done.
    const std::vector<metrics::PixelClass>* classes() const { return done() ? &classes_ : nullptr; }
    // Its measurement pass, which the probe shares (the same frame's surfaces, kept once), and the
    // overlay's size: for the memory breakdown.
    MeasurePass& measurePass() { return pass_; }
    const MeasurePass& measurePass() const { return pass_; }
    int overlayWidth() const { return overlay_.width(); }
    int overlayHeight() const { return overlay_.height(); }

private:
    void start(Renderer& r, const Settings& s, const std::shared_ptr<const Scene>& scene);
    void collect();

    AccuracySchedule schedule_;
    metrics::AccuracyWorker worker_;
    MeasurePass pass_;  // linked at start-up, not in the frame that reads back
    ImageTexture overlay_;
    std::optional<Settings> last_;       // the previous frame's settings, to see a change
    bool wanted_ = false;
    bool measurable_ = false;            // wanted, and the last update's frame was rendered
    double readBackSeconds_ = 0.0;       // of the job in flight
    std::vector<std::string> pendingWarnings_;  // of the job in flight
    metrics::SunDisc sun_;               // the disc of the job in flight
    ui::AccuracyView view_;              // figures (Done) or error (Failed) of the last job
    std::vector<metrics::PixelClass> classes_;  // of the last job that was done
};

}  // namespace st::app
