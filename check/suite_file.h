#pragma once
// A check suite (`shadowtune check SUITE.json`): the presets to replay, each with the image and
// figure tolerances its golden is held to. Read strictly, like presets and sweeps: every error
// names the file, the JSON path and the reason (schema/suite.schema.json, docs/cli.md#check). No GL.
//
//   {
//     "version": 1,
//     "defaults": {"size": "320x180",
//                  "image": {"max_channel_diff": 5, "max_failing_share": 0.001},
//                  "figures": [{"figure": "misclassified", "worse_by_at_most_pp": 0.05}]},
//     "presets": ["../*.json", {"preset": "../vsm11.json", "figures": [{"figure": "flicker", "max": 0}]}]
//   }
#include "check/figure_check.h"
#include "check/image_diff.h"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace st::check {

inline constexpr int kSuiteVersion = 1;

// What a golden made by another renderer means: a failure (RENDERER_MISMATCH), or a comparison
// as usual with the mismatch noted.
enum class OnRendererMismatch { Fail, Compare };

struct SuiteEntry {
    std::filesystem::path preset;  // resolved against the suite file's folder
    std::string name;              // the preset file's stem: the golden's folder and the report's name
    std::optional<std::pair<int, int>> size;  // width, height; none: the preset's own
    ImageTolerance image;
    std::vector<FigureTolerance> figures;  // the defaults', with this entry's rows replacing same-figure ones
    OnRendererMismatch onRendererMismatch = OnRendererMismatch::Fail;
    std::string note;  // shown in the report beside the preset
};

struct Suite {
    std::filesystem::path file;
    std::vector<SuiteEntry> entries;  // in the suite's order, globs expanded (sorted), each preset once
};

// A bad suite: the file, the JSON path ("/presets/2/figures/0/max") and the reason.
class SuiteError : public std::runtime_error {
public:
    SuiteError(std::filesystem::path file, std::string jsonPath, std::string reason);
    const std::filesystem::path& file() const { return file_; }
    const std::string& jsonPath() const { return path_; }
    const std::string& reason() const { return reason_; }

private:
    std::filesystem::path file_;
    std::string path_, reason_;
};

// Throws SuiteError.
Suite loadSuite(const std::filesystem::path& file);

// The entries whose name matches the shell glob `pattern` (fnmatch); all when it is empty.
std::vector<SuiteEntry> selectEntries(const std::vector<SuiteEntry>& entries, const std::string& pattern);

}  // namespace st::check
