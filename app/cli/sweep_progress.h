#pragma once
// The sweep's progress line: one bar redrawn in place on a terminal, a plain line per point
// otherwise (logs of CI jobs and batch schedulers).
#include "sweep/sweep_run.h"

#include <cstdio>

namespace st::app {

class SweepProgress {
public:
    explicit SweepProgress(std::FILE* out);
    void operator()(const sweep::Progress& p);
    void finish();  // ends the bar's line

private:
    std::FILE* out_;
    bool terminal_;
    bool drawn_ = false;
};

std::string durationText(double seconds);  // "42 s", "3 min 05 s", "1 h 02 min"

}  // namespace st::app
