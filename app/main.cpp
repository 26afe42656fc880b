// shadowtune: entry point. Parses the command line and hands over to a command.
#include "app/render_command.h"
#include "renderer/settings/enum_names.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <regex>

namespace {

void addRenderCommand(CLI::App& cli, st::app::RenderOptions& opt, std::string& view, std::string& size) {
    CLI::App* render = cli.add_subcommand("render", "Replay presets headless (EGL) into PNG images and frame statistics");
    render->add_option("presets", opt.presets, "Preset JSON files")->required();
    render->add_option("--out", opt.outDir, "Output folder (created if missing)")->capture_default_str();
    render->add_option("--view", view, "Override the view: shaded, cascades, shadow, texel-density");
    render->add_option("--size", size, "Override the output size, WxH (e.g. 1280x720)");
    render->add_flag("--debug-gl", opt.debugContext, "Debug context; GL errors fail the preset");
    render->add_option("--frames", opt.frames, "Render each preset N times and print median times (benchmark)")
        ->check(CLI::Range(1, 10000));
}

bool applyOverrides(st::app::RenderOptions& opt, const std::string& view, const std::string& size) {
    if (!view.empty()) {
        std::optional<st::View> v = st::parseEnum<st::View>(view);
        if (!v) {
            std::fprintf(stderr, "error: --view: unknown view '%s'\n", view.c_str());
            return false;
        }
        opt.view = *v;
    }
    if (!size.empty()) {
        std::smatch m;
        if (!std::regex_match(size, m, std::regex(R"((\d{1,5})x(\d{1,5}))")) ||
            std::stoi(m[1]) < 16 || std::stoi(m[2]) < 16 || std::stoi(m[1]) > 8192 || std::stoi(m[2]) > 8192) {
            std::fprintf(stderr, "error: --size: expected WxH with 16..8192 each, got '%s'\n", size.c_str());
            return false;
        }
        opt.width = std::stoi(m[1]);
        opt.height = std::stoi(m[2]);
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"shadowtune: tune cascaded shadow maps"};
    cli.require_subcommand(1);
    st::app::RenderOptions renderOpt;
    std::string view, size;
    addRenderCommand(cli, renderOpt, view, size);
    CLI11_PARSE(cli, argc, argv);
    if (cli.got_subcommand("render")) {
        if (!applyOverrides(renderOpt, view, size)) return 2;
        return st::app::runRender(renderOpt);
    }
    return 0;
}
