#pragma once
// Shared by the fuzz targets: a check that aborts whatever NDEBUG says (the fuzz preset is
// RelWithDebInfo), a verbose switch, and a private scratch folder in RAM.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#define ST_FUZZ_CHECK(cond)                                                                         \
    do {                                                                                            \
        if (!(cond)) {                                                                              \
            std::fprintf(stderr, "%s:%d: fuzz check failed: %s\n", __FILE__, __LINE__, #cond);     \
            std::abort();                                                                           \
        }                                                                                           \
    } while (false)

namespace st::fuzz {

// ST_FUZZ_VERBOSE=1: the targets print each input's outcome (to check what the seeds reach).
inline bool verbose() {
    static const bool on = std::getenv("ST_FUZZ_VERBOSE") != nullptr;
    return on;
}

// A new folder for this process, removed at exit. In $ST_FUZZ_TMPDIR, else /dev/shm, else the
// system temp folder: the targets write a file per input, and on a disk (ext4 flushes a file that
// is truncated and rewritten) that costs most of the time of an execution.
inline std::filesystem::path makeScratchDir(const char* prefix) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path base;
    if (const char* dir = std::getenv("ST_FUZZ_TMPDIR")) base = dir;
    else if (fs::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0) base = "/dev/shm";
    else base = fs::temp_directory_path();
    std::string dir = (base / (std::string(prefix) + "-XXXXXX")).string();
    if (::mkdtemp(dir.data()) == nullptr) {
        std::perror("fuzz: mkdtemp");
        std::abort();
    }
    static std::string removeAtExit;  // one scratch folder per process
    removeAtExit = dir;
    std::atexit([] {
        std::error_code ignored;
        fs::remove_all(removeAtExit, ignored);
    });
    return dir;
}

}  // namespace st::fuzz
