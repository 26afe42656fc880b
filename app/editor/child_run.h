#pragma once
// What the editor's background runs (the Sweep and Tune panels) share: a fresh folder per run, a
// child process of this binary with its output in a log, and its last lines when it fails.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace st::app {

// A new empty folder $TMPDIR/<prefix>-XXXXXX (or /tmp); throws std::runtime_error.
std::filesystem::path newRunFolder(const std::string& prefix);

// A relative glTF path made absolute against presetDir, so a preset written elsewhere loads it.
std::string absoluteScene(const std::string& scene, const std::filesystem::path& presetDir);

// Starts args[0] with args, stdin from /dev/null, stdout and stderr into `log`: the child's pid,
// or -1 with `error` set.
pid_t spawnLogged(const std::vector<std::string>& args, const std::filesystem::path& log, std::string& error);

// SIGINT, then up to 5 s for the child to finish what it is measuring, then SIGKILL; reaps it.
void stopChild(pid_t child);

// One background run of a child process, as the Sweep and Tune panels keep it: started, polled
// once a frame (has it ended? is it time to look at its output again?), cancelled with its
// Ctrl-C, stopped (SIGINT, then SIGKILL) when the panel goes away.
class ChildRun {
public:
    using Clock = std::chrono::steady_clock;
    explicit ChildRun(Clock::duration scanInterval) : scanInterval_(scanInterval) {}
    ~ChildRun() { stopChild(pid_); }
    ChildRun(const ChildRun&) = delete;
    ChildRun& operator=(const ChildRun&) = delete;

    // spawnLogged; false with `error` set when it could not start.
    bool start(const std::vector<std::string>& args, const std::filesystem::path& log, std::string& error);
    bool running() const { return pid_ > 0; }
    void interrupt() const;  // SIGINT: the child keeps what it measured and ends
    double elapsedSeconds() const { return std::chrono::duration<double>(Clock::now() - started_).count(); }

    struct Poll {
        std::optional<int> ended;  // the waitpid status, once the child has ended (it is reaped)
        bool scan = false;         // running, and scanInterval has passed since the last scan
    };
    Poll poll();

private:
    Clock::duration scanInterval_;
    pid_t pid_ = -1;
    Clock::time_point started_, lastScan_;
};

// The last `count` non-empty lines of `file`.
std::vector<std::string> lastLines(const std::filesystem::path& file, std::size_t count);

// "exit code 3" or "signal 11", from a waitpid status.
std::string exitText(int status);

}  // namespace st::app
