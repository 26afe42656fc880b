#pragma once
// The HTML report of a check run: one self-contained folder (index.html with its CSS and script
// inline, and the images beside it) that works from file:// with no server and no network. Per
// preset the golden, actual and diff images, golden and actual under one slider, and the figures
// with their deltas; failures first, a filter box. Every string taken from a preset, suite or
// file is escaped (check/markup.h). No GL.
#include "check/check_run.h"
#include "check/results_json.h"

#include <filesystem>
#include <string>
#include <vector>

namespace st::check {

// Writes REPORT/<index-name>/{golden,actual,diff}.png for `r` (those that exist) and sets r's
// *Png to them, relative to REPORT.
void writePresetImages(const std::filesystem::path& reportDir, std::size_t index, PresetResult& r, const Rgba8Image& actual,
                       const Golden* golden, const ImageTolerance& tol);

std::string reportHtml(const RunInfo& info, const std::vector<PresetResult>& results);

// REPORT/index.html and REPORT/results.json, atomically; the folder is created if needed.
void writeReport(const std::filesystem::path& reportDir, const RunInfo& info, const std::vector<PresetResult>& results);

}  // namespace st::check
