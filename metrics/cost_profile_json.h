#pragma once
// A cost profile (metrics/cost_model.h) as JSON: what `shadowtune calibrate` writes and every
// command that reports modelled cost reads. Read strictly: every problem names the file, the JSON
// path and the reason. No GL.
//
//   {"version": 1, "renderer": "llvmpipe (LLVM 15.0.7, 256 bits)", "machine": "...", "date": "...",
//    "frames": 5, "fittedOn": "min",
//    "passes": {"cascade": {"coefficients": {"intercept": 0.4, "fragments": 2.1e-6}, "r2": 0.97, "samples": 60},
//               "main": {...}, "filter": {...},
//               "depthBounds": {..., "calibrated": "Intel Xeon ..., 2026-12-03T03:50:00Z"}},
//    "residuals": [{"preset": "default", "pass": "cascade 0", "minMs": 3.1, "medianMs": 3.4, "modelMs": 3.0}]}
//
// "calibrated" (optional) names where and when a kind was refitted alone (`calibrate --refit`).
// Coefficients are milliseconds per unit of the feature (per fragment, per vertex, ...).
#include "metrics/cost_model.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace st::metrics {

inline constexpr int kCostProfileVersion = 1;

class CostProfileError : public std::runtime_error {
public:
    // what(): "FILE: JSON.PATH: REASON" ("(top level)" for the root).
    CostProfileError(const std::string& file, const std::string& jsonPath, const std::string& reason);
    const std::string& jsonPath() const noexcept { return path_; }

private:
    std::string path_;
};

nlohmann::ordered_json toJson(const CostProfile& p);
// `file` names the source in errors. Throws CostProfileError.
CostProfile costProfileFromJson(const nlohmann::ordered_json& root, const std::string& file);
CostProfile loadCostProfile(const std::filesystem::path& file);  // CostProfileError, also for I/O and syntax
void saveCostProfileAtomic(const CostProfile& p, const std::filesystem::path& file);  // std::runtime_error

}  // namespace st::metrics
