#pragma once
// `shadowtune check SUITE.json --golden DIR`: replays a suite's presets headless, renders and
// measures each as `measure` does, and holds the frame and figures to their goldens
// (check/check_run.h). Exit 0: all pass; 1: a regression, a golden missing or a preset that
// failed; 2: cannot run (a bad suite, no GL context).
#include <filesystem>
#include <string>

namespace st::app {

struct CheckCommandOptions {
    std::filesystem::path suite;
    std::filesystem::path golden;
    bool update = false;             // write the goldens (and print what changed)
    std::filesystem::path reportDir; // index.html, results.json and images; empty: none
    std::filesystem::path junit;     // JUnit XML file; empty: none
    std::string only;                // shell glob over preset names; empty: all
};

int runCheck(const CheckCommandOptions& opt);

}  // namespace st::app
