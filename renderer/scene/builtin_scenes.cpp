// Deterministic procedural scenes: the few objects that show each effect, nothing more.
#include "renderer/scene/scene.h"

#include <functional>
#include <map>

namespace st {
namespace {
int addMaterial(Scene& s, glm::vec3 rgb) {
    Material m;
    m.baseColor = glm::vec4(rgb, 1.0f);
    s.materials.push_back(m);
    return static_cast<int>(s.materials.size()) - 1;
}

// Near boxes and thin poles (cascade 0 detail), a few medium-range buildings, a tall tower far
// away whose long shadow only the last cascades can hold: 1 vs 4 cascades differ visibly.
Scene makeYard() {
    Scene s;
    int ground = addMaterial(s, {0.55f, 0.6f, 0.45f});
    int stone = addMaterial(s, {0.75f, 0.72f, 0.68f});
    int wood = addMaterial(s, {0.6f, 0.42f, 0.28f});
    int brick = addMaterial(s, {0.7f, 0.4f, 0.35f});
    addGroundQuad(s, 300.0f, 0.0f, ground);
    addBox(s, {-3.0f, 0.0f, 0.0f}, {-1.5f, 1.5f, 1.5f}, stone);
    addBox(s, {1.0f, 0.0f, -2.0f}, {2.0f, 1.0f, -1.0f}, stone);
    addBox(s, {-0.6f, 0.0f, -6.0f}, {0.6f, 2.5f, -4.8f}, wood);
    for (int i = 0; i < 5; ++i) {  // thin poles: 8 cm wide, 3 m tall
        float x = -4.0f + 2.0f * static_cast<float>(i);
        addBox(s, {x - 0.04f, 0.0f, -9.0f}, {x + 0.04f, 3.0f, -8.92f}, wood);
    }
    addBox(s, {-18.0f, 0.0f, -35.0f}, {-10.0f, 6.0f, -27.0f}, brick);
    addBox(s, {8.0f, 0.0f, -50.0f}, {16.0f, 9.0f, -42.0f}, brick);
    addBox(s, {-4.0f, 0.0f, -80.0f}, {4.0f, 4.0f, -72.0f}, stone);
    addBox(s, {-45.0f, 0.0f, -230.0f}, {-37.0f, 60.0f, -222.0f}, stone);  // the far tower
    finalizeBounds(s);
    return s;
}

// One 2 m box floating 2 m over a plane: its shadow is an exact projection for checks.
Scene makeBoxOverPlane() {
    Scene s;
    int ground = addMaterial(s, {0.8f, 0.8f, 0.8f});
    int box = addMaterial(s, {0.8f, 0.5f, 0.3f});
    addGroundQuad(s, 20.0f, 0.0f, ground);
    addBox(s, {-1.0f, 2.0f, -1.0f}, {1.0f, 4.0f, 1.0f}, box);
    finalizeBounds(s);
    return s;
}

Scene makeEmpty() {
    Scene s;
    addMaterial(s, {0.8f, 0.8f, 0.8f});
    finalizeBounds(s);
    return s;
}

// A 40 m tower, 3 m wide, 30 m behind a camera that looks down -Z (presets/scenarios/tower-*):
// the tower is outside the view frustum, its long shadow falls into view.
Scene makeTowerOutside() {
    Scene s;
    int ground = addMaterial(s, {0.8f, 0.8f, 0.8f});
    int stone = addMaterial(s, {0.75f, 0.72f, 0.68f});
    addGroundQuad(s, 150.0f, 0.0f, ground);
    addBox(s, {-1.5f, 0.0f, 38.5f}, {1.5f, 40.0f, 41.5f}, stone);
    finalizeBounds(s);
    return s;
}

// Slats 3 m over the ground, 0.25 m wide every 1 m, 70 m long along the view (-Z): striped
// shadows that cross every split depth, where a seam between cascades shows.
Scene makePergola() {
    Scene s;
    int ground = addMaterial(s, {0.8f, 0.8f, 0.8f});
    int wood = addMaterial(s, {0.6f, 0.42f, 0.28f});
    addGroundQuad(s, 120.0f, 0.0f, ground);
    for (int i = 0; i < 9; ++i) {
        const float x = -4.0f + static_cast<float>(i);
        addBox(s, {x, 3.0f, -70.0f}, {x + 0.25f, 3.2f, 0.0f}, wood);
    }
    finalizeBounds(s);
    return s;
}

// One wall standing on the ground, 12 m along X, 3 m tall, 0.3 m thick: a face that a sun at
// azimuth 0 or 180 grazes exactly (N.L = 0 on both long faces).
Scene makeWall() {
    Scene s;
    int ground = addMaterial(s, {0.8f, 0.8f, 0.8f});
    int brick = addMaterial(s, {0.7f, 0.4f, 0.35f});
    addGroundQuad(s, 30.0f, 0.0f, ground);
    addBox(s, {-6.0f, 0.0f, -0.15f}, {6.0f, 3.0f, 0.15f}, brick);
    finalizeBounds(s);
    return s;
}

// Two stacked casters over the ground (presets/scenarios/vsm-bleeding-*): a low slab 1.5 m up
// and 12.5 m above it, along a sun at azimuth 0 and elevation 25, slats that cover half of the
// slab in the light's view. On the ground in the slab's shadow a filter window holds two
// blocker depths, slats and slab, far apart compared to the slab's height over the ground: the
// variance of the mixed window makes Chebyshev's bound read light where the truth is umbra
// (seed 004, "Light Bleeding"). The slats reach the slab's footprint in the light's view at
// x + (14 - 1.5) / tan(25 deg) = x + 26.8.
Scene makeStackedSlabs() {
    Scene s;
    int ground = addMaterial(s, {0.8f, 0.8f, 0.8f});
    int stone = addMaterial(s, {0.75f, 0.72f, 0.68f});
    int wood = addMaterial(s, {0.6f, 0.42f, 0.28f});
    addGroundQuad(s, 40.0f, 0.0f, ground);
    addBox(s, {-2.0f, 1.5f, -3.0f}, {2.0f, 1.7f, 3.0f}, stone);
    // 0.5 m slats every 1 m, 5 cm thick: across the light at 25 deg each covers 0.5 sin 25 +
    // 0.05 cos 25 = 0.26 m and leaves a 0.17 m gap (a thicker slat would close the gaps).
    for (int i = 0; i < 5; ++i) {
        const float x = 24.8f + static_cast<float>(i);
        addBox(s, {x, 14.0f, -3.5f}, {x + 0.5f, 14.05f, 3.5f}, wood);
    }
    finalizeBounds(s);
    return s;
}

const std::map<std::string, std::function<Scene()>>& builtins() {
    static const std::map<std::string, std::function<Scene()>> table = {
        {"yard", makeYard},           {"box-over-plane", makeBoxOverPlane}, {"empty", makeEmpty},
        {"tower-outside", makeTowerOutside}, {"pergola", makePergola},     {"wall", makeWall},
        {"stacked-slabs", makeStackedSlabs}};
    return table;
}
}  // namespace

std::vector<std::string> builtinSceneNames() {
    std::vector<std::string> names;
    for (const auto& [name, make] : builtins()) names.push_back(name);
    return names;
}

Scene makeBuiltinScene(const std::string& name) {
    auto it = builtins().find(name);
    if (it == builtins().end()) {
        std::string known;
        for (const auto& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
        throw SceneError("unknown built-in scene 'builtin:" + name + "' (known: " + known + ")");
    }
    Scene s = it->second();
    s.name = "builtin:" + name;
    return s;
}

}  // namespace st
