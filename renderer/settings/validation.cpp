#include "renderer/settings/validation.h"

#include "renderer/settings/enum_names.h"
#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/number_text.h"
#include "renderer/settings/split_range.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace st {
namespace {

bool isFloatKind(FieldKind kind) {
    return kind == FieldKind::Float || kind == FieldKind::Vec3 || kind == FieldKind::FloatList;
}

std::string rangeText(const FieldInfo& field) {
    return formatNumber(field.min) + ".." + formatNumber(field.max);
}

// Float fields: the value is checked as the float it will be stored as, against float bounds.
std::optional<std::string> checkFloatRange(const FieldInfo& field, double value) {
    if (std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
        return "must be in " + rangeText(field) + ", got " + formatNumber(value);
    }
    const auto stored = static_cast<float>(value);
    if (stored < static_cast<float>(field.min) || stored > static_cast<float>(field.max)) {
        return "must be in " + rangeText(field) + ", got " + formatFloat(stored);
    }
    return std::nullopt;
}

std::optional<std::string> checkIntRules(const FieldInfo& field, double value) {
    if (value < field.min || value > field.max) {
        return "must be in " + rangeText(field) + ", got " + formatNumber(value);
    }
    const auto n = static_cast<std::int64_t>(value);
    if (field.powerOfTwo && (n & (n - 1)) != 0) {
        return "must be a power of two in " + rangeText(field) + ", got " + formatNumber(value);
    }
    if (field.odd && n % 2 == 0) return "must be odd, got " + formatNumber(value);
    return std::nullopt;
}

void checkElements(const FieldInfo& field, const float* values, std::size_t count, const std::string& path,
                   std::vector<SettingsIssue>& out) {
    for (std::size_t i = 0; i < count; ++i) {
        if (auto reason = checkNumber(field, values[i])) out.push_back({path + "[" + std::to_string(i) + "]", *reason});
    }
}

void checkFieldAt(const FieldInfo& field, const FieldValue& value, const std::string& path,
                  std::vector<SettingsIssue>& out);

// Each keyframe member (keyframeFieldTable()) follows the rule of the camera field of the same name.
void checkKeyframes(const std::vector<CameraKeyframe>& frames, std::vector<SettingsIssue>& out) {
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const std::string prefix = "path.keyframes[" + std::to_string(i) + "].";
        for (const KeyframeFieldInfo& m : keyframeFieldTable())
            checkFieldAt(m.field, m.get(frames[i]), prefix + std::string(m.field.path), out);
    }
}

// `path` names the value in messages: the field's path, or a keyframe member's.
void checkFieldAt(const FieldInfo& field, const FieldValue& value, const std::string& path,
                  std::vector<SettingsIssue>& out) {
    std::optional<std::string> reason;
    switch (field.kind) {
        case FieldKind::Float: reason = checkNumber(field, std::get<float>(value)); break;
        case FieldKind::Int: reason = checkNumber(field, std::get<int>(value)); break;
        case FieldKind::Bool: break;
        case FieldKind::Enum: {
            const int index = std::get<int>(value);
            if (index < 0 || static_cast<std::size_t>(index) >= field.enumNames.size()) {
                reason = "must be one of " + quotedNames(field.enumNames) + ", got invalid value " + std::to_string(index);
            }
            break;
        }
        case FieldKind::String:
            if (field.nonEmpty && std::get<std::string>(value).empty()) reason = "must not be empty";
            break;
        case FieldKind::Vec3: checkElements(field, &std::get<glm::vec3>(value).x, 3, path, out); break;
        case FieldKind::FloatList: {
            const auto& list = std::get<std::vector<float>>(value);
            checkElements(field, list.data(), list.size(), path, out);
            break;
        }
        case FieldKind::IntList: {
            const auto& list = std::get<std::vector<int>>(value);
            for (std::size_t i = 0; i < list.size(); ++i)
                if (auto why = checkNumber(field, list[i])) out.push_back({path + "[" + std::to_string(i) + "]", *why});
            break;
        }
        case FieldKind::KeyframeList: checkKeyframes(std::get<std::vector<CameraKeyframe>>(value), out); break;
    }
    if (reason) out.push_back({path, *reason});
}

void checkField(const FieldInfo& field, const FieldValue& value, std::vector<SettingsIssue>& out) {
    checkFieldAt(field, value, std::string(field.path), out);
}

// ---- Cross-field rules ------------------------------------------------------------------------

struct CrossRule {
    std::string_view description;
    std::vector<std::string_view> inputs;  // field paths the rule reads
    void (*check)(const Settings&, std::vector<SettingsIssue>&);
};

void checkNearFar(const Settings& s, std::vector<SettingsIssue>& out) {
    if (s.camera.nearPlane < s.camera.farPlane) return;
    out.push_back({"camera.farPlane", "must be greater than camera.nearPlane (" + formatFloat(s.camera.nearPlane) +
                                          "), got " + formatFloat(s.camera.farPlane)});
}

void checkBleedRemap(const Settings& s, std::vector<SettingsIssue>& out) {
    if (s.filter.bleedLow < s.filter.bleedHigh) return;
    out.push_back({"filter.bleedHigh", "must be greater than filter.bleedLow (" + formatFloat(s.filter.bleedLow) + "), got " +
                                           formatFloat(s.filter.bleedHigh)});
}

void checkCasterOffsetUnit(const Settings& s, std::vector<SettingsIssue>& out) {
    if (s.bias.normalOffsetSide != NormalOffsetSide::CasterSin || s.bias.normalOffsetUnit == OffsetUnit::Metres) return;
    out.push_back({"bias.normalOffsetUnit", "must be \"metres\" when bias.normalOffsetSide is \"caster-sin\" (the casters move "
                                            "before any cascade's texel is known), got \"texels\""});
}

void checkTarget(const Settings& s, std::vector<SettingsIssue>& out) {
    if (s.camera.target != s.camera.position) return;
    out.push_back({"camera.target", "must differ from camera.position, or the view direction is undefined"});
}

void checkShadowDistance(const Settings& s, std::vector<SettingsIssue>& out) {
    const float d = s.cascades.shadowDistance;
    if (d == 0.0f || (d > s.camera.nearPlane && d <= s.camera.farPlane)) return;
    out.push_back({"cascades.shadowDistance", "must be 0 (the far plane) or in (camera.nearPlane, camera.farPlane] = (" +
                                                  formatFloat(s.camera.nearPlane) + ", " +
                                                  formatFloat(s.camera.farPlane) + "], got " + formatFloat(d)});
}

void checkManualSplits(const Settings& s, std::vector<SettingsIssue>& out) {
    const CascadeSettings& c = s.cascades;
    if (c.scheme != SplitScheme::Manual) return;
    const auto needed = static_cast<std::size_t>(c.count - 1);
    if (c.manualSplits.size() != needed) {
        out.push_back({"cascades.manualSplits", "the manual scheme with " + std::to_string(c.count) +
                                                    " cascades needs exactly " + std::to_string(needed) +
                                                    " split depths, got " + std::to_string(c.manualSplits.size())});
        return;
    }
    const bool byDistance = c.shadowDistance > 0.0f;
    const float end = splitRangeEnd(s.camera, c);
    const std::string interval = std::string("(camera.nearPlane, ") +
                                 (byDistance ? "cascades.shadowDistance" : "camera.farPlane") + ") = (" +
                                 formatFloat(s.camera.nearPlane) + ", " + formatFloat(end) + ")";
    for (std::size_t i = 0; i < needed; ++i) {
        const float split = c.manualSplits[i];
        const std::string path = "cascades.manualSplits[" + std::to_string(i) + "]";
        if (i > 0 && !(split > c.manualSplits[i - 1])) {
            out.push_back({path, "must be greater than the previous split (" + formatFloat(c.manualSplits[i - 1]) +
                                     "), got " + formatFloat(split)});
        } else if (!(split > s.camera.nearPlane && split < end)) {
            out.push_back({path, "must be in " + interval + ", got " + formatFloat(split)});
        }
    }
}

void checkUpdateInterval(const Settings& s, std::vector<SettingsIssue>& out) {
    for (std::size_t i = 0; i < s.cascades.updateInterval.size(); ++i) {
        const float k = s.cascades.updateInterval[i];
        if (k == std::floor(k)) continue;
        out.push_back({"cascades.updateInterval[" + std::to_string(i) + "]",
                       "must be a whole number of frames, got " + formatFloat(k)});
    }
}

// A texture array has one size for every layer; an atlas tile or a texture of its own can have any.
void checkMapSizes(const Settings& s, std::vector<SettingsIssue>& out) {
    const CascadeSettings& c = s.cascades;
    if (c.mapSizes.empty()) return;
    if (c.storage == CascadeStorage::Array) {
        out.push_back({"cascades.mapSizes", "the array storage gives every layer one size (cascades.mapSize); "
                                            "per-cascade sizes need cascades.storage \"atlas\" or \"textures\""});
        return;
    }
    if (c.mapSizes.size() != static_cast<std::size_t>(c.count))
        out.push_back({"cascades.mapSizes", "needs one size per cascade (" + std::to_string(c.count) + "), got " +
                                                std::to_string(c.mapSizes.size())});
}

void checkPathKeyframes(const Settings& s, std::vector<SettingsIssue>& out) {
    if (s.path.frames > 0 && s.path.keyframes.empty())
        out.push_back({"path.keyframes", "path.frames is " + std::to_string(s.path.frames) +
                                             ", so the path needs at least one keyframe"});
    for (std::size_t i = 0; i < s.path.keyframes.size(); ++i) {
        if (s.path.keyframes[i].target != s.path.keyframes[i].position) continue;
        out.push_back({"path.keyframes[" + std::to_string(i) + "].target",
                       "must differ from its position, or the view direction is undefined"});
    }
}

void checkGround(const Settings& s, std::vector<SettingsIssue>& out) {
    // A second quad at the built-in ground's height would z-fight with it.
    if (s.ground && s.scene.starts_with("builtin:"))
        out.push_back({"ground", "must be false for " + s.scene + ", which has its own ground"});
}

// Each filter kind samples the storages its descriptor lists (renderer/settings/kind_descriptors.h):
// the moment maps hold one layer per cascade of one texture array (renderer/render/moment_maps.h);
// PCSS's blocker search reads raw depths from the one depth texture of the array or the atlas (the
// per-cascade textures are bound with depth compare only).
void checkFilterStorage(const Settings& s, std::vector<SettingsIssue>& out) {
    if (storageSupports(s.filter.kind, s.cascades.storage)) return;
    std::string names;
    for (CascadeStorage storage : describe(s.filter.kind).storages)
        names += (names.empty() ? "\"" : "\" or \"") + std::string(enumName(storage));
    const std::string why = isMomentFilter(s.filter.kind)
                                ? "the moment maps hold one layer per cascade of one texture array"
                                : "the blocker search reads raw depths from one depth texture";
    out.push_back({"filter.kind", "\"" + std::string(enumName(s.filter.kind)) + "\" needs cascades.storage " + names +
                                      "\", got \"" + std::string(enumName(s.cascades.storage)) + "\": " + why});
}

// A per-cascade bias scale list is empty (1 for every cascade) or holds one factor per cascade.
void checkBiasScales(const Settings& s, std::vector<SettingsIssue>& out) {
    const auto count = static_cast<std::size_t>(s.cascades.count);
    const std::pair<const char*, const std::vector<float>*> lists[] = {{"bias.constantScale", &s.bias.constantScale},
                                                                      {"bias.slopeScale", &s.bias.slopeScale},
                                                                      {"bias.normalOffsetScale", &s.bias.normalOffsetScale}};
    for (const auto& [path, list] : lists) {
        if (list->empty() || list->size() == count) continue;
        out.push_back({path, "needs one factor per cascade (cascades.count " + std::to_string(count) + ") or none, got " +
                                 std::to_string(list->size())});
    }
}

const std::vector<CrossRule>& crossRules() {
    static const std::vector<CrossRule> rules = {
        {"camera.nearPlane must be less than camera.farPlane.", {"camera.nearPlane", "camera.farPlane"}, checkNearFar},
        {"camera.target must differ from camera.position.", {"camera.position", "camera.target"}, checkTarget},
        {"filter.bleedLow must be less than filter.bleedHigh.", {"filter.bleedLow", "filter.bleedHigh"}, checkBleedRemap},
        {"bias.normalOffsetSide \"caster-sin\" takes bias.normalOffsetUnit \"metres\".",
         {"bias.normalOffsetSide", "bias.normalOffsetUnit"},
         checkCasterOffsetUnit},
        {"cascades.shadowDistance must be 0 (use the far plane) or in (camera.nearPlane, camera.farPlane].",
         {"camera.nearPlane", "camera.farPlane", "cascades.shadowDistance"},
         checkShadowDistance},
        {"With scheme \"manual\", cascades.manualSplits holds exactly count-1 strictly increasing depths in "
         "(camera.nearPlane, end), end being cascades.shadowDistance if > 0, else camera.farPlane.",
         {"camera.nearPlane", "camera.farPlane", "cascades.shadowDistance", "cascades.count", "cascades.scheme",
          "cascades.manualSplits"},
         checkManualSplits},
        {"cascades.updateInterval holds whole numbers of frames (entries past cascades.count are unused).",
         {"cascades.updateInterval"},
         checkUpdateInterval},
        {"cascades.mapSizes, when given, holds one size per cascade and needs storage \"atlas\" or \"textures\".",
         {"cascades.count", "cascades.storage", "cascades.mapSizes"},
         checkMapSizes},
        {"path.frames > 0 needs at least one keyframe; each keyframe's target must differ from its position.",
         {"path.frames", "path.keyframes"},
         checkPathKeyframes},
        {"ground is for glTF scenes; built-in scenes have their own.", {"scene", "ground"}, checkGround},
        {"Each filter.kind needs a cascades.storage it can sample: the moment filters (vsm, evsm2, evsm4, msm) "
         "\"array\", \"pcss\" \"array\" or \"atlas\".",
         {"filter.kind", "cascades.storage"},
         checkFilterStorage},
        {"bias.constantScale, bias.slopeScale and bias.normalOffsetScale are empty or hold one factor per cascade.",
         {"cascades.count", "bias.constantScale", "bias.slopeScale", "bias.normalOffsetScale"},
         checkBiasScales},
    };
    return rules;
}

// "cascades.manualSplits[2]" -> "cascades.manualSplits"
std::string_view fieldOf(std::string_view path) { return path.substr(0, path.find('[')); }

bool anyIn(const std::vector<std::string_view>& paths, const PathSet& set) {
    for (const auto path : paths) {
        if (set.contains(path)) return true;
    }
    return false;
}

}  // namespace

std::optional<std::string> checkNumber(const FieldInfo& field, double value) {
    if (!std::isfinite(value)) return "must be finite, got " + formatNumber(value);
    if (isFloatKind(field.kind)) return checkFloatRange(field, value);
    return checkIntRules(field, value);
}

std::vector<SettingsIssue> findIssues(const Settings& s, const PathSet& untrusted) {
    std::vector<SettingsIssue> issues;
    for (const FieldInfo& field : fieldTable()) {
        if (!untrusted.contains(field.path)) checkField(field, field.get(s), issues);
    }
    PathSet bad = untrusted;
    for (const CrossRule& rule : crossRules()) {
        for (const auto& issue : issues) bad.emplace(fieldOf(issue.path));
        if (!anyIn(rule.inputs, bad)) rule.check(s, issues);
    }
    return issues;
}

std::vector<std::string> validate(const Settings& s) {
    std::vector<std::string> messages;
    for (const auto& issue : findIssues(s)) messages.push_back(issue.message());
    return messages;
}

std::vector<std::string_view> crossFieldRuleDescriptions() {
    std::vector<std::string_view> descriptions;
    for (const CrossRule& rule : crossRules()) descriptions.push_back(rule.description);
    return descriptions;
}

}  // namespace st
