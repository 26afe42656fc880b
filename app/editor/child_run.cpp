#include "app/editor/child_run.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace st::app {
namespace fs = std::filesystem;

fs::path newRunFolder(const std::string& prefix) {
    std::error_code ec;
    fs::path tmp = fs::temp_directory_path(ec);
    if (ec) tmp = "/tmp";
    std::string pattern = (tmp / (prefix + "-XXXXXX")).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a folder under " + tmp.string());
    return pattern;
}

std::string absoluteScene(const std::string& scene, const fs::path& presetDir) {
    if (scene.rfind("builtin:", 0) == 0 || fs::path(scene).is_absolute()) return scene;
    return fs::absolute(presetDir / scene).lexically_normal().string();
}

pid_t spawnLogged(const std::vector<std::string>& args, const fs::path& log, std::string& error) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<std::string> copy = args;
    std::vector<char*> argv;
    for (std::string& s : copy) argv.push_back(s.data());
    argv.push_back(nullptr);
    pid_t child = -1;
    const int rc = ::posix_spawn(&child, copy[0].c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc == 0) return child;
    error = "cannot run " + args[0] + ": " + std::strerror(rc);
    return -1;
}

void stopChild(pid_t child) {
    if (child <= 0) return;
    ::kill(child, SIGINT);
    for (int i = 0; i < 100; ++i) {  // the evaluation or point under way: a few seconds at most
        if (::waitpid(child, nullptr, WNOHANG) == child) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
}

bool ChildRun::start(const std::vector<std::string>& args, const fs::path& log, std::string& error) {
    pid_ = spawnLogged(args, log, error);
    started_ = Clock::now();
    lastScan_ = started_ - scanInterval_;  // the first poll scans
    return pid_ > 0;
}

void ChildRun::interrupt() const {
    if (pid_ > 0) ::kill(pid_, SIGINT);
}

ChildRun::Poll ChildRun::poll() {
    Poll p;
    if (pid_ <= 0) return p;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        p.ended = status;
        return p;
    }
    const Clock::time_point now = Clock::now();
    if (now - lastScan_ >= scanInterval_) p.scan = true, lastScan_ = now;
    return p;
}

std::vector<std::string> lastLines(const fs::path& file, std::size_t count) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    if (lines.size() > count) lines.erase(lines.begin(), lines.end() - long(count));
    return lines;
}

std::string exitText(int status) {
    return WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status)) : "signal " + std::to_string(WTERMSIG(status));
}

}  // namespace st::app
