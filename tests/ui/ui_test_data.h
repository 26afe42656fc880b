#pragma once
// Inputs the UI tests give EditorUi in place of a renderer: plausible frame statistics and a
// scratch folder for presets.
#include "renderer/render/frame_stats.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace st::test {

// Four cascades of a 400 m view with practical splits, 1024^2 maps.
inline FrameStats fakeFrameStats(float wobble = 0.0f) {
    FrameStats stats;
    stats.splits = {0.1f, 6.2f, 24.5f, 92.0f, 400.0f};
    const float extents[] = {9.0f, 31.0f, 110.0f, 420.0f};
    for (int i = 0; i < 4; ++i) {
        CascadeStats c;
        c.vsNear = stats.splits[static_cast<std::size_t>(i)];
        c.vsFar = stats.splits[static_cast<std::size_t>(i) + 1];
        c.lsExtent = {extents[i], extents[i] * 0.9f, 140.0f + 20.0f * float(i)};
        c.texelWorldSize = extents[i] / 1024.0f;
        c.casterDraws = 40 + 25 * i;
        c.casterTriangles = static_cast<std::size_t>(3000 + 4000 * i);
        c.gpuMs = 0.3 + 0.1 * i + wobble * 0.05;
        stats.cascades.push_back(c);
    }
    stats.shadowMapBytes = 4u * 1024u * 1024u * 4u;
    stats.gpuShadowMs = 1.8 + wobble * 0.2;
    stats.gpuMainMs = 2.4 + wobble * 0.3;
    stats.cpuMs = 0.6;
    stats.sceneTriangles = 48000;
    stats.width = 1280;
    stats.height = 720;
    return stats;
}

// A fresh folder per test, removed afterwards.
class ScratchFolder {
public:
    ScratchFolder() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path = std::filesystem::path(::testing::TempDir()) /
               ("ui_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~ScratchFolder() { std::filesystem::remove_all(path); }
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name) << text;
        return path / name;
    }
    std::filesystem::path path;
};

}  // namespace st::test
