#include "app/cli/sweep_progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace st::app {

std::string durationText(double seconds) {
    const long s = std::lround(std::max(seconds, 0.0));
    char text[32];
    if (s < 60) std::snprintf(text, sizeof text, "%ld s", s);
    else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
    else std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, s / 60 % 60);
    return text;
}

SweepProgress::SweepProgress(std::FILE* out) : out_(out), terminal_(::isatty(::fileno(out)) == 1) {}

void SweepProgress::operator()(const sweep::Progress& p) {
    const std::string eta = p.etaS < 0.0 ? "ETA -" : "ETA " + durationText(p.etaS);
    const std::string counts = std::to_string(p.done) + "/" + std::to_string(p.total) +
                               (p.resumed ? " (" + std::to_string(p.resumed) + " resumed)" : "");
    if (!terminal_) {
        std::fprintf(out_, "sweep: %s done, %s elapsed, %s: %s\n", counts.c_str(), durationText(p.elapsedS).c_str(),
                     eta.c_str(), p.label.c_str());
        std::fflush(out_);
        return;
    }
    constexpr int kWidth = 30;
    const int filled = p.total ? int(double(kWidth) * double(p.done) / double(p.total)) : kWidth;
    std::string bar = "[" + std::string(std::size_t(filled), '#') + std::string(std::size_t(kWidth - filled), '.') + "]";
    std::string line = bar + " " + counts + "  " + durationText(p.elapsedS) + " elapsed, " + eta + "  " + p.label;
    if (line.size() > 150) line = line.substr(0, 147) + "...";
    std::fprintf(out_, "\r\033[K%s", line.c_str());
    std::fflush(out_);
    drawn_ = true;
}

void SweepProgress::finish() {
    if (drawn_) std::fprintf(out_, "\n");
    drawn_ = false;
}

}  // namespace st::app
