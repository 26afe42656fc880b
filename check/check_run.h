#pragma once
// One preset's verdict against its golden, and what an --update would change. Pure: the app
// renders and measures, this compares. No GL.
//
// Statuses (after Filament's renderdiff): PASS; FAILED (the image or a figure out of tolerance:
// an accuracy regression fails even when the image is within its tolerance); GOLDEN_MISSING;
// RENDERER_MISMATCH (the golden was made by another renderer and the suite does not say to
// compare anyway); ERROR (the preset could not be replayed); with --update: NEW, UPDATED, UNCHANGED.
#include "check/figure_check.h"
#include "check/golden_store.h"
#include "check/image_diff.h"
#include "check/suite_file.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace st::check {

enum class Status { Pass, Failed, GoldenMissing, RendererMismatch, Error, New, Updated, Unchanged };
const char* statusName(Status s);  // "PASS", "GOLDEN_MISSING", ...
bool isFailure(Status s);          // FAILED, GOLDEN_MISSING, RENDERER_MISMATCH, ERROR

// What a replay gave: the frame, its figures (metrics.json's content) and its metadata.
struct Actual {
    Rgba8Image image;
    nlohmann::ordered_json figures;
    GoldenMeta meta;
};

// One figure of the table in both runs, for the report (checked or not).
struct FigureRowResult {
    const metrics::FigureRow* row = nullptr;
    std::optional<double> golden, actual;
    std::optional<FigureVerdict> verdict;  // when the suite checks it
};

struct PresetResult {
    std::string name;
    std::string preset;  // the preset file, as the suite resolved it
    std::string note;
    Status status = Status::Error;
    std::string goldenDir;
    std::string message;  // one line: why it failed, or what changed
    std::vector<std::string> notes;  // renderer mismatch compared anyway, settings hash changed, ...
    std::optional<ImageDiff> image;
    std::string imageTolerance;
    std::vector<FigureRowResult> figures;  // every repeatable figure of the table: failing checks, other checks, the rest
    std::vector<FigureVerdict> checks;     // the suite's figure tolerances, in its order
    double seconds = 0.0;
    // Images as written into the report folder, relative to it ("" when not written).
    std::string goldenPng, actualPng, diffPng;
};

// The figure `row` in a metrics.json, or nothing when absent or null.
std::optional<double> figureIn(const nlohmann::ordered_json& figures, const metrics::FigureRow& row);

// The verdict of `actual` against `golden` (none: GOLDEN_MISSING).
PresetResult judge(const SuiteEntry& e, const Actual& actual, const std::optional<Golden>& golden);

// --update: NEW, UNCHANGED (same image bytes and figures) or UPDATED, with what changed in
// `notes` ("misclassified 1.2 % -> 1.3 % (+0.1 pp)", "image: 12 pixels ...").
PresetResult updateVerdict(const SuiteEntry& e, const Actual& actual, const std::optional<Golden>& golden);

// 0 when no result is a failure, else 1.
int exitCodeOf(const std::vector<PresetResult>& results);

// Failures first (in the suite's order), then the rest.
std::vector<const PresetResult*> failuresFirst(const std::vector<PresetResult>& results);

}  // namespace st::check
