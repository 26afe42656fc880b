#include "ui/field_overrides.h"

#include "renderer/csm/limits.h"
#include "renderer/scene/scene.h"
#include "ui/document_actions.h"
#include "renderer/settings/enum_names.h"
#include "ui/field_rules.h"
#include "ui/field_widgets.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <span>
#include <variant>

namespace st::ui {
namespace {

constexpr std::string_view kBuiltin = "builtin:";

bool isBuiltin(const std::string& scene) { return scene.starts_with(kBuiltin); }

// The glTF path field shows the scene when it is a file; it keeps what the user types otherwise.
void syncGltfText(UiState& state, const std::string& scene) {
    if (scene == state.gltfTextFor) return;
    state.gltfTextFor = scene;
    if (!isBuiltin(scene)) state.gltfText = scene;
}

// A scene that does not load never reaches the settings (issue 13 #1): the settings, the history
// and the view stay as they were and the reason is shown under the field until it changes.
bool storeScene(const FieldInfo& field, UiFrame& f, const std::string& chosen) {
    if (chosen == f.s.scene) return false;
    if (std::string error = sceneProblem(f, chosen, f.s.ground, documentFolder(f.state)); !error.empty()) {
        f.state.sceneError = std::move(error);
        f.state.sceneErrorFor = chosen;
        return false;
    }
    f.state.sceneError.clear();
    return storeField(field, f.s, chosen);
}

void drawSceneError(UiFrame& f) {
    if (f.state.sceneError.empty()) return;
    if (f.state.gltfText != f.state.sceneErrorFor && !isBuiltin(f.state.sceneErrorFor)) {
        f.state.sceneError.clear();  // the path was edited since
        return;
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
    ImGui::TextWrapped("Not loaded: %s", f.state.sceneError.c_str());
    ImGui::PopStyleColor();
    recordItem(f.state.rects, "scene.error");
}

bool drawBuiltinCombo(const FieldInfo& field, UiFrame& f, const std::string& scene) {
    std::string chosen = scene;
    const std::string preview = isBuiltin(scene) ? scene : "glTF file";
    if (ImGui::BeginCombo(std::string(field.label).c_str(), preview.c_str())) {
        for (const auto& name : builtinSceneNames()) {
            const std::string spec = std::string(kBuiltin) + name;
            if (ImGui::Selectable(spec.c_str(), spec == scene)) chosen = spec;
        }
        ImGui::EndCombo();
    }
    recordItem(f.state.rects, std::string(field.path));
    drawHelpMarker(field);
    return storeScene(field, f, chosen);
}

bool drawGltfPath(const FieldInfo& field, UiFrame& f) {
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - 45.0f);
    const bool entered = ImGui::InputTextWithHint("##gltf", "path/to/scene.gltf", &f.state.gltfText,
                                                  ImGuiInputTextFlags_EnterReturnsTrue);
    recordItem(f.state.rects, "scene.gltf");
    ImGui::SameLine();
    const bool use = ImGui::Button("Use");
    ImGui::SameLine();
    ImGui::TextUnformatted("glTF file");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A .gltf/.glb path, relative to the preset's folder; Enter or Use loads it.");
    if (!(entered || use) || f.state.gltfText.empty()) return false;
    return storeScene(field, f, f.state.gltfText);
}

bool drawScene(const FieldInfo& field, UiFrame& f) {
    const FieldValue value = field.get(f.s);
    const auto* scene = std::get_if<std::string>(&value);
    if (!scene) return drawFieldWidget(field, f.s, f.state.rects, f.state.fieldEdits);
    syncGltfText(f.state, *scene);
    const bool picked = drawBuiltinCombo(field, f, *scene);
    const bool typed = drawGltfPath(field, f);
    drawSceneError(f);
    return picked || typed;
}

bool drawMapSize(const FieldInfo& field, UiFrame& f) {
    const int count = f.s.cascades.count;
    const bool changed = editPowerOfTwo(field, f.s, [count](int size) {
        return "(" + formatBytes(csm::shadowMapBytes(count, size)) + ")";
    }, &f.state.rects);
    recordItem(f.state.rects, std::string(field.path));
    drawHelpMarker(field);
    const int size = f.s.cascades.mapSize;
    if (f.s.cascades.storage == CascadeStorage::Array) {
        ImGui::TextDisabled("  %d x %d x %d x %zu B = %s of shadow maps", count, size, size, csm::kShadowTexelBytes,
                            formatBytes(csm::shadowMapBytes(count, size)).c_str());
    } else if (f.in.stats) {
        // An atlas's padding and packing, or sizes per cascade: the renderer's own figure.
        ImGui::TextDisabled("  %s of shadow maps (%s storage, last frame)", formatBytes(f.in.stats->shadowMapBytes).c_str(),
                            enumName(f.s.cascades.storage).c_str());
    }
    return changed;
}

std::span<const float> rendererSplits(const UiFrame& f) {
    if (!f.in.stats) return {};
    return f.in.stats->splits;
}

bool drawManualSplits(const FieldInfo& field, UiFrame& f) {
    if (f.s.cascades.scheme != SplitScheme::Manual) return false;
    const FieldValue value = field.get(f.s);
    const auto* stored = std::get_if<std::vector<float>>(&value);
    if (!stored) return drawFieldWidget(field, f.s, f.state.rects, f.state.fieldEdits);
    std::vector<float> splits = fitManualSplits(f.s, rendererSplits(f));
    editFloatElements(field, splits, f.state.rects, f.state.fieldEdits);
    return storeField(field, f.s, splits);
}

// A row per cascade, greyed, each at the factor of 1 an empty list means: the Bias section shows
// every cascade's row whether or not it has a value of its own (issue 21 #5).
void drawSingleValueRows(const FieldInfo& field, int count, ItemRects& rects) {
    ImGui::BeginDisabled();
    for (int i = 0; i < count; ++i) {
        ImGui::PushID(i);
        float one = 1.0f;
        ImGui::DragFloat(elementLabel(field, std::size_t(i)).c_str(), &one, 0.0f, 1.0f, 1.0f, "%.2f x (the same for all)");
        ImGui::PopID();
        recordItem(rects, std::string(field.path) + "[" + std::to_string(i) + "]#single");
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("One value for every cascade. Per cascade gives each its own factor.");
}

// bias.constantScale, slopeScale, normalOffsetScale: empty (1 for every cascade) offers "Per
// cascade", which starts from count factors of 1 (the image unchanged); a list shows a factor per
// cascade and "Same for all", which empties it again.
bool drawBiasScale(const FieldInfo& field, UiFrame& f) {
    const FieldValue value = field.get(f.s);
    const auto* stored = std::get_if<std::vector<float>>(&value);
    if (!stored) return drawFieldWidget(field, f.s, f.state.rects, f.state.fieldEdits);
    std::vector<float> factors = *stored;
    const std::string unused = notApplicableReason(field, f.s);
    if (!unused.empty()) ImGui::PushStyleVar(ImGuiStyleVar_Alpha, ImGui::GetStyle().Alpha * 0.45f);
    bool changed = false;
    if (factors.empty()) {
        ImGui::TextUnformatted(std::string(field.label).c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("Per cascade")) {
            factors.assign(static_cast<std::size_t>(f.s.cascades.count), 1.0f);
            changed = true;
        }
        recordItem(f.state.rects, std::string(field.path) + "#perCascade");
        drawSingleValueRows(field, f.s.cascades.count, f.state.rects);
    } else {
        changed = editFloatElements(field, factors, f.state.rects, f.state.fieldEdits);
        if (ImGui::SmallButton("Same for all")) {
            factors.clear();
            changed = true;
        }
        recordItem(f.state.rects, std::string(field.path) + "#sameForAll");
    }
    if (!unused.empty()) {
        ImGui::PopStyleVar();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", unused.c_str());
    }
    recordItem(f.state.rects, std::string(field.path) + (unused.empty() ? "" : "#unused"));
    recordItem(f.state.rects, std::string(field.path));
    drawHelpMarker(field);
    return changed && storeField(field, f.s, factors);
}

}  // namespace

FieldOverride overrideFor(std::string_view path) {
    if (path == "scene") return drawScene;
    if (path == "cascades.mapSize") return drawMapSize;
    if (path == "cascades.manualSplits") return drawManualSplits;
    if (path == "bias.constantScale" || path == "bias.slopeScale" || path == "bias.normalOffsetScale") return drawBiasScale;
    return nullptr;
}

}  // namespace st::ui
