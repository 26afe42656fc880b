// Where the search starts: the input, the cheapest settings, analytic biases, seen-by views.
#include "tune/tuner.h"

#include "metrics/cost.h"
#include "metrics/figure_table.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "sweep/sweep_results.h"
#include "sweep/sweep_spec.h"
#include "tune/tune_engine.h"
#include "tune/tune_eval.h"
#include "tune/tune_explain.h"
#include "tune/tune_holdout.h"
#include "tune/tune_journal.h"
#include "tune/tune_views.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

namespace st::tune::detail {

Settings cheapest(Settings s) {
    s.cascades.count = 1;
    s.cascades.mapSize = 256;
    s.cascades.mapSizes.clear();
    s.cascades.manualSplits.clear();
    if (s.cascades.scheme == SplitScheme::Manual) s.cascades.scheme = SplitScheme::Practical;
    s.cascades.depthBounds = DepthBounds::Off;
    s.cascades.fit = FitMode::Cascade;
    s.cascades.blendBand = 0.0f;
    s.filter.kind = FilterKind::Hard;
    s.filter.screenSpace = ScreenSpace::Off;
    s.filter.contact = ContactShadows::Off;
    return s;
}

Settings texelBias(Settings s) {
    s.bias.constant = 0.0f;
    s.bias.slope = 1.0f;
    s.bias.normalOffset = 0.5f;
    return s;
}

Settings planeBias(Settings s) {
    s.bias.constant = 0.0f;
    s.bias.slope = 0.5f;
    s.bias.normalOffset = 0.0f;
    s.bias.receiverPlane = true;
    return s;
}

Settings seenBy(Settings s) {
    s.cascades.fit = FitMode::Samples;
    s.cascades.selection = Selection::Map;
    s.cascades.zExtension = ZExtension::Distance;
    s.cascades.zExtensionDistance = float(farPlaneShare(s, kZExtensionStartShare));
    return planeBias(s);
}

Settings seenNear(Settings s) {
    s = seenBy(s);
    const float reach = float(farPlaneShare(s, kZExtensionStartShare));
    if (s.cascades.shadowDistance <= 0.0f || s.cascades.shadowDistance > reach) s.cascades.shadowDistance = reach;
    return s;
}

std::vector<Settings> starts(const Settings& input) {
    Settings seen = input;
    seen.cascades.depthBounds = DepthBounds::Fit;
    seen.cascades.fit = FitMode::Samples;
    return {input, seen, texelBias(seen), planeBias(seen)};
}

Settings screenSize(Settings s) {
    s.output.width = std::max(16, s.output.width / 2);
    s.output.height = std::max(16, s.output.height / 2);
    return s;
}

void widenLimits(Objective& o, const std::vector<std::pair<std::string, double>>& more) {
    for (const auto& [key, limit] : more)
        for (auto& [k, l] : o.atMost)
            if (k == key) l = std::max(l, limit);
}

}  // namespace st::tune::detail
