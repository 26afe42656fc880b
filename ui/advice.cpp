#include "ui/advice.h"

#include "ui/field_rules.h"

#include <cstdio>

namespace st::ui {
namespace {

std::string joinChoices(const std::vector<std::string>& choices) {
    std::string text;
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (i > 0) text += i + 1 == choices.size() ? " or " : ", ";
        text += choices[i];
    }
    return text;
}

std::string number(const char* format, double value) {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

std::string share(double s) { return number("%.2f %%", 100.0 * s); }

// What moves texels toward the camera, given what the settings already do.
std::vector<std::string> finerTexelChoices(const Settings& s) {
    const CascadeSettings& c = s.cascades;
    std::vector<std::string> choices;
    if (c.shadowDistance <= 0.0f || c.shadowDistance > 0.5f * s.camera.farPlane)
        choices.push_back(c.shadowDistance <= 0.0f ? "set a shadow distance (now the far plane, " +
                                                         formatLength(s.camera.farPlane) + ")"
                                                   : "lower the shadow distance (" + formatLength(c.shadowDistance) + ")");
    if (c.scheme == SplitScheme::Practical && c.lambda < 0.95f) choices.push_back("raise lambda (" + number("%.2f", c.lambda) + ")");
    if (c.scheme == SplitScheme::Uniform) choices.push_back("use the practical split scheme");
    if (c.count < 8) choices.push_back("add a cascade (" + std::to_string(c.count) + ")");
    if (c.mapSize < 4096) choices.push_back("raise the map size (" + std::to_string(c.mapSize) + ")");
    return choices;
}

}  // namespace

std::vector<Advice> adviseFromFigures(const Settings& s, const FrameStats& stats) {
    int worst = -1;
    for (std::size_t i = 0; i < stats.cascades.size(); ++i)
        if (stats.cascades[i].texelWorldSize > kCoarseTexelMetres &&
            (worst < 0 || stats.cascades[i].texelWorldSize > stats.cascades[std::size_t(worst)].texelWorldSize))
            worst = int(i);
    if (worst < 0) return {};
    const CascadeStats& c = stats.cascades[std::size_t(worst)];
    std::string text = "Cascade " + std::to_string(worst) + " texel is " + formatLength(c.texelWorldSize) + " (" +
                       formatLength(c.vsNear) + " - " + formatLength(c.vsFar) +
                       "): small objects there get no shadow of their own shape.";
    const std::vector<std::string> choices = finerTexelChoices(s);
    if (!choices.empty()) text += " Try: " + joinChoices(choices) + ".";
    return {{"coarse-texel", text}};
}

std::vector<Advice> adviseFromAccuracy(const Settings& s, const AccuracyView& a) {
    std::vector<Advice> out;
    if (a.state != AccuracyView::State::Done || a.all.receivers == 0) return out;
    const BiasSettings& b = s.bias;
    const double acne = a.all.share(a.all.falseShadowGross);
    if (acne > kGrossShare) {
        std::string text = "Gross false shadow on " + share(acne) + " of sun-facing pixels: acne. Raise the slope bias (" +
                           number("%.2f", b.slope) + ")";
        if (!b.receiverPlane) text += ", or enable the receiver-plane bias";
        out.push_back({"acne", text + "."});
    }
    const double panning = a.all.share(a.all.falseLightGross);
    if (panning > kGrossShare) {
        std::string text = "False light on " + share(panning) + " of sun-facing pixels, at contacts: peter-panning. ";
        if (b.normalOffset > 0.0f) text += "Lower the normal offset (" + number("%.2f", b.normalOffset) + " texels).";
        else if (b.constant > 0.0f) text += "Lower the constant bias (" + formatLength(b.constant) + ").";
        else text += "Lower the slope bias (" + number("%.2f", b.slope) + ").";
        out.push_back({"peter-panning", text});
    }
    return out;
}

}  // namespace st::ui
