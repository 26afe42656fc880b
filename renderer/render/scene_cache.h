#pragma once
// Loaded scenes and their renderers, kept per scene (sceneKey: spec, folder, options) so presets
// that name the same scene share one CPU copy and one GPU upload. `render` and `measure` use it;
// measure keeps each scene's BVH beside it in `Extra`. Needs a current GL context.
#include "renderer/render/renderer.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace st {

struct SceneSlot {
    std::unique_ptr<Scene> scene;
    std::unique_ptr<Renderer> renderer;  // draws `scene`: declared after it, destroyed before it
};

struct NoSceneExtra {};

template <class Extra = NoSceneExtra>
class SceneCache {
public:
    // Extra's members sit beside the scene and renderer (e.g. measure's `truth`). Bases are
    // destroyed in reverse order, so whatever Extra builds over the scene goes before the scene.
    struct Entry : SceneSlot, Extra {};

    SceneCache() = default;
    // keepOne: loading a scene first drops every other scene and its renderer. Timing runs want
    // it: on llvmpipe a frame of truck-town took 25-45 % longer after another scene's renderer
    // had been used in the same context than in a fresh one (issue 18, docs/cost-model.md).
    explicit SceneCache(bool keepOne) : keepOne_(keepOne) {}

    // The entry of s's scene (relative glTF paths resolve against presetDir), loaded and uploaded
    // on first use. Throws SceneError or what Renderer throws; a failed load leaves no entry.
    Entry& entryFor(const Settings& s, const std::filesystem::path& presetDir) {
        const SceneOptions options{.ground = s.ground};
        const std::string key = sceneKey(s.scene, presetDir, options);
        if (auto it = entries_.find(key); it != entries_.end()) return it->second;
        if (keepOne_) entries_.clear();
        auto scene = std::make_unique<Scene>(loadScene(s.scene, presetDir, options));
        auto renderer = std::make_unique<Renderer>(*scene);
        Entry& e = entries_[key];
        e.scene = std::move(scene);
        e.renderer = std::move(renderer);
        return e;
    }

    Renderer& rendererFor(const Settings& s, const std::filesystem::path& presetDir) {
        return *entryFor(s, presetDir).renderer;
    }

    std::size_t size() const { return entries_.size(); }  // scenes loaded and kept

private:
    std::map<std::string, Entry> entries_;  // a map: entries stay put while others are added
    bool keepOne_ = false;
};

}  // namespace st
