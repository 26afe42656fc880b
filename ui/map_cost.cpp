#include "ui/map_cost.h"

#include "renderer/csm/storage_layout.h"
#include "renderer/settings/enum_names.h"
#include "ui/field_rules.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace st::ui {

double cascadeTexels(const CascadeSettings& c) {
    double texels = 0.0;
    for (int i = 0; i < c.count; ++i) {
        const double side = csm::cascadeMapSize(c, i);
        texels += side * side;
    }
    return texels;
}

std::optional<double> measuredMsPerTexel(const FrameStats& stats, const CascadeSettings& rendered) {
    double ms = 0.0, texels = 0.0;
    for (std::size_t i = 0; i < stats.cascades.size(); ++i) {
        const CascadeStats& cs = stats.cascades[i];
        if (!cs.redrawn || cs.gpuMs <= 0.0) continue;
        const double side = cs.mapSize > 0 ? cs.mapSize : csm::cascadeMapSize(rendered, static_cast<int>(i));
        ms += cs.gpuMs;
        texels += side * side;
    }
    if (texels <= 0.0) return std::nullopt;
    return ms / texels;
}

std::optional<double> modelledMsPerTexel(const FrameStats& stats, const CascadeSettings& rendered) {
    const double texels = cascadeTexels(rendered);
    if (stats.modelShadowMs <= 0.0 || texels <= 0.0) return std::nullopt;
    return stats.modelShadowMs / texels;
}

MapCost mapCost(const CascadeSettings& c, std::optional<double> msPerTexel, bool modelled, std::optional<FrameBase> base) {
    MapCost cost;
    cost.modelled = modelled && msPerTexel.has_value();
    try {
        cost.bytes = csm::storageBytes(csm::planStorage(c));
    } catch (const std::invalid_argument&) {
        // e.g. array storage with different sizes: validation names the reason, nothing is allocated
    }
    if (!msPerTexel) return cost;
    const double texels = cascadeTexels(c);
    cost.redrawMs = *msPerTexel * texels;
    // Never below the shadow pass alone: a base frame whose maps were kept timed less than a redraw.
    if (base) cost.frameMs = std::max(*cost.redrawMs, base->wallMs + *msPerTexel * (texels - base->texels));
    cost.firstFrameMs = firstFrameMs(cost.frameMs.value_or(*cost.redrawMs), texels);
    return cost;
}

double firstFrameMs(double redrawMs, double newTexels) { return redrawMs + newTexels * kFirstFrameNsPerTexel * 1e-6; }

bool asksFirst(const MapCost& before, const MapCost& after) {
    const bool bytes = after.bytes && *after.bytes > kAskAboveShadowBytes && *after.bytes > before.bytes.value_or(0);
    const bool time = after.redrawMs && *after.redrawMs > kAskAboveRedrawMs && *after.redrawMs > before.redrawMs.value_or(0.0);
    return bytes || time;
}

namespace {

std::string mapsText(const CascadeSettings& c) {
    std::string text;
    if (c.mapSizes.empty()) {
        text = std::to_string(c.count) + " x " + std::to_string(c.mapSize) + " maps";
    } else {
        for (int i = 0; i < c.count; ++i) text += (i ? "/" : "") + std::to_string(csm::cascadeMapSize(c, i));
        text += " maps";
    }
    if (c.storage != CascadeStorage::Array) text += " (" + enumName(c.storage) + ")";
    return text;
}

std::string durationText(double ms) {
    char text[32];
    if (ms >= 1000.0) std::snprintf(text, sizeof text, "%.1f s", ms / 1000.0);
    else std::snprintf(text, sizeof text, "%.0f ms", ms);
    return text;
}

}  // namespace

std::string costQuestion(const CascadeSettings& c, const MapCost& cost) {
    std::string q = mapsText(c) + ":";
    if (cost.bytes) q += " " + formatBytes(*cost.bytes) + " of shadow maps";
    if (cost.redrawMs) {
        q += cost.bytes ? ";" : "";
        // The first frame also makes the maps (issue 39 #7): said apart, so a long first frame is expected.
        if (cost.firstFrameMs) q += " the first frame about " + durationText(*cost.firstFrameMs) + " while the maps are made, then";
        q += " about " + durationText(cost.frameMs.value_or(*cost.redrawMs)) +
             (cost.modelled ? " a redraw (modelled: no shadow pass timed yet)" : " a redraw on this machine");
    }
    return q + ". Apply?";
}

bool affectsMapCost(std::string_view path) {
    return path == "cascades.mapSize" || path == "cascades.mapSizes" || path == "cascades.count" ||
           path == "cascades.storage";
}

}  // namespace st::ui
