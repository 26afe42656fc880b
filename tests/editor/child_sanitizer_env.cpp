// Under the asan build (ST_NO_DLCLOSE_SO defined, tests/editor/CMakeLists.txt), the editor and the
// commands these tests start as child processes get what scripts/asan.sh gives every test, also
// when ctest runs without it (a plain `ctest --preset asan -R EditorXdotool` rerun):
// - tests/sanitizers/no_dlclose.cpp preloaded. Without it Mesa's DRI driver (swrast_dri.so, loaded
//   for GLX) is unloaded as the window closes, and the blocks it never frees are reported as leaks
//   "in an unknown module" (issue 20: the editor exited non-zero, EditorXdotoolTest failed 3 of 3).
//   Their stacks name no module, so no suppression can match them; kept loaded, they stay
//   reachable and nothing is reported.
// - verify_asan_link_order=0, for that library comes before the ASan runtime;
// - the driver stack's suppressions (tests/sanitizers/lsan.supp) unless LSAN_OPTIONS is set.
// Options already set (by scripts/asan.sh, or by hand) are kept.
#include <cstdlib>
#include <string>

#ifdef ST_NO_DLCLOSE_SO
namespace {

std::string env(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

// Set before main: gtest_main starts no thread before it, and every child inherits it.
const bool childSanitizerEnvSet = [] {
    const std::string preload = env("LD_PRELOAD");
    if (preload.find("no_dlclose") == std::string::npos)
        ::setenv("LD_PRELOAD", (ST_NO_DLCLOSE_SO + (preload.empty() ? "" : " " + preload)).c_str(), 1);
    const std::string asan = env("ASAN_OPTIONS");
    ::setenv("ASAN_OPTIONS", ((asan.empty() ? std::string(ST_ASAN_OPTIONS) : asan) + ":verify_asan_link_order=0").c_str(), 1);
    if (env("LSAN_OPTIONS").empty())
        ::setenv("LSAN_OPTIONS", "suppressions=" ST_LSAN_SUPP ":print_suppressions=0", 1);
    return true;
}();

}  // namespace
#endif
