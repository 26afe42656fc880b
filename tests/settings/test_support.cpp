#include "tests/settings/test_support.h"

#include "renderer/settings/settings_json.h"

#include <unistd.h>

#include <algorithm>

namespace st::test {

Settings everyFieldChanged() {
    Settings s;
    s.scene = "scenes/sponza/Sponza.gltf";
    s.notes = "No contact hardening; the source blends cascades in screen space.";
    s.ground = true;
    s.origin = {50000.0f, -12.5f, 2.25f};
    s.camera = {.position = {1.5f, 2.25f, -3.0f}, .target = {0.5f, 0.0f, 1.0f}, .fovY = 45.5f,
                .nearPlane = 0.25f, .farPlane = 250.0f};
    s.light = {.azimuth = -120.5f, .elevation = 12.25f, .intensity = 2.5f, .ambient = 0.3f, .angularDiameter = 1.5f};
    s.cascades = {.count = 3, .scheme = SplitScheme::Manual, .lambda = 0.8f, .manualSplits = {10.0f, 40.5f},
                  .shadowDistance = 150.0f, .depthBounds = DepthBounds::Fit, .mapSize = 2048, .storage = CascadeStorage::Atlas,
                  .mapSizes = {2048, 1024, 512}, .atlasPadding = 4, .fit = FitMode::Sphere, .stabilize = true,
                  .snap = Snap::CentreRound, .sliceCorners = SliceCorners::Float32Inverse,
                  .sphereCentre = SphereCentre::CornersMean,
                  .zExtension = ZExtension::Distance, .zExtensionDistance = 55.5f, .lightDepth = 300.0f,
                  .casterFaces = CasterFaces::Back, .pancakeToCasters = true, .selection = Selection::Map,
                  .blendBand = 0.1f, .casterCulling = false, .updateInterval = {1.0f, 2.0f, 4.0f}, .fadeBand = 0.2f,
                  .cameraRelative = true, .fitFovY = 70.0f, .matricesOneFrameLate = true};
    s.filter = {.kind = FilterKind::PcfNxN, .size = 5, .weights = FilterWeights::Gaussian, .padding = true,
                .blurRadius = 4, .mipmaps = true, .moments16 = true, .minVariance = 2e-5f, .bleedExponent = 3.0f, .bleedLow = 0.2f, .bleedHigh = 0.9f,
                .evsmPositive = 30.0f, .evsmNegative = 4.0f, .momentBias = 5e-5f, .blockerTaps = 7,
                .pcssMaxRadius = 12.0f, .vogelTaps = 7, .radius = 1.5f, .screenSpace = ScreenSpace::Blur, .screenDownsample = 4,
                .screenBlurRadius = 6, .screenDepthSigma = 0.25f, .contact = ContactShadows::March, .contactLength = 1.25f,
                .contactSteps = 20, .contactThickness = 0.75f};
    s.bias = {.constant = 0.005f, .constantUnit = BiasUnit::Depth, .slope = 2.5f, .normalOffset = 1.5f,
              .normalOffsetUnit = OffsetUnit::Metres,
              .normalOffsetSide = NormalOffsetSide::CasterSin, .receiverPlane = true,
              .constantScale = {1.0f, 1.5f, 2.25f}, .slopeScale = {0.5f, 1.0f, 1.0f}, .normalOffsetScale = {1.0f, 1.0f, 3.0f}};
    s.output = {.width = 800, .height = 600, .view = View::Cascades, .texelBlock = 16, .sideTexels = true};
    s.path = {.frames = 12,
              .keyframes = {{.position = {0.0f, 2.0f, 5.0f}, .target = {0.0f, 1.0f, -5.0f}, .fovY = 50.0f},
                            {.position = {0.25f, 2.0f, 5.0f}, .target = {0.25f, 1.0f, -5.0f}, .fovY = 55.5f}}};
    s.measure = {.sunRays = 32, .artifactTexels = 3.5f};
    return s;
}

nlohmann::json preset(const nlohmann::json& patch) {
    nlohmann::json json = {{"version", 1}};
    json.merge_patch(patch);
    return json;
}

std::vector<std::string> readErrors(const nlohmann::json& json) {
    try {
        (void)fromJson(json, kSource);
    } catch (const SettingsError& e) {
        return e.messages();
    }
    ADD_FAILURE() << "fromJson accepted " << json.dump();
    return {};
}

::testing::AssertionResult hasMessage(const std::vector<std::string>& messages, std::string_view part) {
    const bool found = std::any_of(messages.begin(), messages.end(),
                                   [&](const std::string& m) { return m.find(part) != std::string::npos; });
    if (found) return ::testing::AssertionSuccess();
    auto failure = ::testing::AssertionFailure() << "no message contains \"" << part << "\"; messages:";
    for (const auto& m : messages) failure << "\n  " << m;
    return failure;
}

void ScratchDir::SetUp() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = std::filesystem::temp_directory_path() /
          ("settings_test-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "-" + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
}

void ScratchDir::TearDown() { std::filesystem::remove_all(dir); }

std::vector<std::string> ScratchDir::entries() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace st::test
