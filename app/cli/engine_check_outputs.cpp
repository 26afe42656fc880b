#include "app/cli/engine_check_outputs.h"

#include "app/images/legend_image.h"
#include "metrics/engine_agreement.h"
#include "metrics/metric_images.h"
#include "renderer/image/image_io.h"
#include "renderer/settings/settings_json.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

namespace st::app {
namespace fs = std::filesystem;
namespace {

using nlohmann::json;
using Colour = std::array<std::uint8_t, 3>;

constexpr Colour kNone{24, 32, 56}, kAway{60, 45, 80};  // not scored: a dark violet, apart from the greys
constexpr Colour kAgreeLit{235, 235, 235}, kAgreeShadow{110, 110, 110};
constexpr Colour kEngineOnly{220, 40, 40}, kModelOnly{40, 110, 230};

void putColour(Rgba8Image& img, std::size_t i, Colour c) {
    for (int k = 0; k < 3; ++k) img.pixels[4 * i + std::size_t(k)] = c[std::size_t(k)];
    img.pixels[4 * i + 3] = 255;
}

Rgba8Image blankOf(const MeasureSamples& s) {
    return {s.width, s.height, std::vector<std::uint8_t>(s.size() * 4, 255)};
}

// A factor as grey on the receivers; the background navy, surfaces facing away dark grey.
Rgba8Image factorImage(const MeasureSamples& s, const std::vector<float>& factor, const std::vector<float>& coverage) {
    Rgba8Image img = blankOf(s);
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (coverage[i] <= 0.5f) putColour(img, i, kNone);
        else if (!s.receiver(i)) putColour(img, i, kAway);
        else {
            const auto g = std::uint8_t(40.0f + 210.0f * std::clamp(factor[i], 0.0f, 1.0f));
            putColour(img, i, {g, g, g});
        }
    }
    return img;
}

Rgba8Image disagreementImage(const MeasureSamples& s, const std::vector<metrics::AgreementClass>& classes) {
    Rgba8Image img = blankOf(s);
    for (std::size_t i = 0; i < s.size(); ++i) {
        switch (classes[i]) {
            case metrics::AgreementClass::AgreeLit: putColour(img, i, kAgreeLit); break;
            case metrics::AgreementClass::AgreeShadow: putColour(img, i, kAgreeShadow); break;
            case metrics::AgreementClass::EngineOnlyShadow: putColour(img, i, kEngineOnly); break;
            case metrics::AgreementClass::ModelOnlyShadow: putColour(img, i, kModelOnly); break;
            default: putColour(img, i, s.covered(i) ? kAway : kNone); break;
        }
    }
    return img;
}

json figuresOf(const metrics::EngineAgreement& a, const metrics::FactorScore& f) {
    return {{"accuracy.misclassified", a.misclassified(f)},
            {"accuracy.falseShadow", a.scored ? double(f.falseShadow) / double(a.scored) : 0.0},
            {"accuracy.falseLight", a.scored ? double(f.falseLight) / double(a.scored) : 0.0},
            {"soft.filteredError", a.filteredError(f)}};
}

json engineInfo(const fs::path& file) {
    try {
        return loadJsonFile(file, "engine result");
    } catch (const std::exception&) {
        return json::object();
    }
}

// The model's pixels in the engine's layout (engines/README.md "The page interface"): per pixel,
// rows top first, the filtered factor, the cascade (-1 beyond the shadows), N.L and coverage.
void writeModelSamples(const fs::path& file, const MeasureSamples& s) {
    std::vector<float> v(s.size() * 4);
    for (std::size_t i = 0; i < s.size(); ++i) {
        v[4 * i] = s.shadow[i].y;
        v[4 * i + 1] = s.covered(i) ? s.shadow[i].z : -1.0f;
        v[4 * i + 2] = s.normal[i].w;
        v[4 * i + 3] = s.covered(i) ? 1.0f : 0.0f;
    }
    fs::create_directories(file.parent_path());
    writeTextAtomic(file, std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float)));
}

}  // namespace

int writeEngineCheck(const EngineCheckOptions& opt, const xport::EngineKnobs& knobs, const metrics::PresetMeasurement& m,
                     const std::vector<glm::vec4>& engine, double seconds) {
    const MeasureSamples& s = m.samples;
    std::vector<metrics::AgreementClass> classes;
    const metrics::EngineAgreement a = metrics::compareWithEngine(engine, s, m.truth, m.softTruth.visible, &classes);
    std::vector<float> fe(s.size()), fm(s.size()), ce(s.size()), cm(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        fe[i] = engine[i].x, ce[i] = engine[i].w;
        fm[i] = s.shadow[i].y, cm[i] = s.covered(i) ? 1.0f : 0.0f;
    }
    const std::string name = xport::engineName(opt.engine);
    const json info = engineInfo(opt.outDir / "engine" / "engine.json");
    const std::string version = info.value("version", std::string("?"));
    std::array<std::size_t, 5> counts{};
    for (metrics::AgreementClass c : classes) ++counts[std::size_t(c)];
    std::size_t sky = 0;
    for (std::size_t i = 0; i < s.size(); ++i) sky += s.covered(i) ? 0 : 1;
    const std::size_t away = counts[std::size_t(metrics::AgreementClass::NotScored)] - sky;
    const std::vector<metrics::LegendEntry> factorKey{{"facing away", kAway, away}, {"no surface", kNone, sky}};
    char pct[64];
    std::snprintf(pct, sizeof pct, "%.2f %%", 100.0 * a.agreement());
    writeImageAtomic(opt.outDir / "engine.png",
                     withLegend(factorImage(s, fe, ce), name + " " + version + ": its own shadow factor, dark 0 (shadowed) .. white 1 (lit)", factorKey));
    writeImageAtomic(opt.outDir / "model.png", withLegend(factorImage(s, fm, cm), "shadowtune's model of the same settings, dark 0 .. white 1", factorKey));
    writeImageAtomic(opt.outDir / "truth.png", withLegend(metrics::truthImage(s, m.truth), "ray-cast truth (lit, shadowed)", {}));
    writeImageAtomic(opt.outDir / "disagreement.png",
                     withLegend(disagreementImage(s, classes), "engine vs model: " + std::string(pct) + " of scored pixels agree",
                                {{"both lit", kAgreeLit, counts[std::size_t(metrics::AgreementClass::AgreeLit)]},
                                 {"both shadowed", kAgreeShadow, counts[std::size_t(metrics::AgreementClass::AgreeShadow)]},
                                 {"only " + name + " shadowed", kEngineOnly, a.engineOnlyShadow},
                                 {"only shadowtune shadowed", kModelOnly, a.modelOnlyShadow},
                                 {"not scored (facing away)", kAway, away},
                                 {"no surface", kNone, sky}}));
    // The model snaps vertices to the grid of --subpixel-bits; an engine on another grid puts its
    // acne stripes elsewhere (docs/engines.md "The rasterizer's grid"), so a mismatch is said.
    std::optional<int> engineBits;
    if (const auto it = info.find("info"); it != info.end() && it->contains("subpixelBits") && (*it)["subpixelBits"].is_number_integer())
        engineBits = (*it)["subpixelBits"].get<int>();
    if (engineBits && *engineBits != opt.subpixelBits)
        std::fprintf(stderr, "warning: %s rasterized with %d sub-pixel bits, the model with %d (--subpixel-bits %d matches it)\n",
                     name.c_str(), *engineBits, opt.subpixelBits, *engineBits);
    const json figures = {{"engine", {{"name", name}, {"version", version}, {"figures", figuresOf(a, a.engine)}}},
                          {"model", {{"figures", figuresOf(a, a.model)}}},
                          {"agreement", a.agreement()},
                          {"factorAgreement", a.factorAgreement()},
                          {"meanFactorDifference", a.meanFactorDifference()},
                          {"borderlinePixels", a.borderline},
                          {"scoredPixels", a.scored},
                          {"engineMissingPixels", a.engineMissing},
                          {"size", {s.width, s.height}},
                          {"knobs", knobs.knobs},
                          {"lacks", knobs.lacks},
                          {"subpixelBits", {{"engine", engineBits ? json(*engineBits) : json(nullptr)}, {"model", opt.subpixelBits}}},
                          {"engineTimings", info.value("timings", json::object())},
                          {"seconds", seconds}};
    writeTextAtomic(opt.outDir / "figures.json", figures.dump(2) + "\n");
    writeModelSamples(opt.outDir / "model" / "samples.f32", s);
    if (opt.quiet) return 0;
    std::printf("%-22s %14s %14s\n", "", (name + " " + version).c_str(), "shadowtune");
    std::printf("%-22s %13.3f%% %13.3f%%\n", "misclassified", 100.0 * a.misclassified(a.engine), 100.0 * a.misclassified(a.model));
    std::printf("%-22s %14.4f %14.4f\n", "filtered error", a.filteredError(a.engine), a.filteredError(a.model));
    std::printf("agreement %s of %zu scored pixels (%dx%d), %zu receiver pixels the engine did not draw; %.1f s -> %s\n", pct,
                a.scored, s.width, s.height, a.engineMissing, seconds, opt.outDir.string().c_str());
    std::printf("factors: mean |engine - model| %.4f; %.2f %% agree in state or within %.1f (%zu borderline pixels)\n",
                a.meanFactorDifference(), 100.0 * a.factorAgreement(), double(metrics::kBorderlineFactor), a.borderline);
    return 0;
}

}  // namespace st::app
