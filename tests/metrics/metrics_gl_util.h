#pragma once
// Helpers of the metrics GL tests: presets at test size and one measured frame.
#include "metrics/measure_session.h"
#include "renderer/settings/settings_json.h"

#include <string>

namespace st::test {

// A shipped preset at 320x180 (the golden tests' size: fast on two cores).
inline Settings presetAtTestSize(const std::string& name, int width = 320, int height = 180) {
    Settings s = loadPreset(std::string(ST_PRESET_DIR) + "/" + name + ".json");
    s.output.width = width;
    s.output.height = height;
    return s;
}

// Ground truth, accuracy and density of `s`; no cost or flicker (their own tests run them).
inline metrics::PresetMeasurement measureStill(metrics::MeasureSession& session, const Settings& s) {
    metrics::MeasureOptions opt;
    opt.cost = false;
    opt.flicker = false;
    return session.measure(s, ST_PRESET_DIR, opt);
}

}  // namespace st::test
