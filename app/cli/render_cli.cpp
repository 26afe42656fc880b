// `shadowtune render`: command-line options of headless replay.
#include "app/cli/commands.h"
#include "app/cli/number_checks.h"
#include "app/cli/render_command.h"
#include "app/cli/warning_options.h"
#include "renderer/settings/enum_names.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <string_view>

namespace st::app {
namespace {

struct RenderArgs {
    RenderOptions opt;
    std::string view;
    std::string size;
};

bool applyOverrides(RenderArgs& a) {
    if (!a.view.empty()) {
        std::optional<View> v = parseEnum<View>(a.view);
        if (!v) {
            std::fprintf(stderr, "error: --view: unknown view '%s'\n", a.view.c_str());
            return false;
        }
        a.opt.view = *v;
    }
    if (!a.size.empty()) {
        std::smatch m;
        if (!std::regex_match(a.size, m, std::regex(R"((\d{1,5})x(\d{1,5}))")) || std::stoi(m[1]) < 16 ||
            std::stoi(m[2]) < 16 || std::stoi(m[1]) > 8192 || std::stoi(m[2]) > 8192) {
            std::fprintf(stderr, "error: --size: expected WxH with 16..8192 each, got '%s'\n", a.size.c_str());
            return false;
        }
        a.opt.width = std::stoi(m[1]);
        a.opt.height = std::stoi(m[2]);
    }
    return true;
}

// "shaded, cascades, ...": every View the settings name, so the help never lags the enum.
std::string viewNames() {
    std::string text;
    for (const std::string_view name : enumNames<View>()) text += (text.empty() ? "" : ", ") + std::string(name);
    return text;
}

}  // namespace

void addRenderCommand(CLI::App& cli, int& exitCode) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* render = cli.add_subcommand("render", "Replay presets headless (EGL) into PNG images and frame statistics");
    render->add_option("presets", args->opt.presets, "Preset JSON files")->required();
    render->add_option("--out", args->opt.outDir, "Output folder (created if missing)")->capture_default_str();
    render->add_option("--view", args->view, "Override the view: " + viewNames());
    render->add_option("--size", args->size, "Override the output size, WxH (e.g. 1280x720)");
    render->add_option("--profile", args->opt.costProfile,
                       "Cost profile of the modelled cost (default: the shipped llvmpipe profile)");
    render->add_flag("--debug-gl", args->opt.debugContext, "Debug context; GL errors fail the preset");
    render->add_option("--frames", args->opt.frames, "Time N frames of each preset (after an untimed warm-up, every map redrawn) and print median, minimum and maximum")
        ->check(numberIn(1, 10000));
    addWarningOptions(*render, args->opt.warningLimits);
    render->callback([args, &exitCode] { exitCode = applyOverrides(*args) ? runRender(args->opt) : 2; });
}

}  // namespace st::app
