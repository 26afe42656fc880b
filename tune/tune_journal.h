#pragma once
// The tune's journal: every evaluation made, one JSON line each, appended and flushed as soon as
// it is measured, so Ctrl-C (or a crash) keeps them and the same command resumes without measuring
// them again. A line cut short by a kill is ignored on reading. No GL.
#include "renderer/settings/settings.h"
#include "tune/tune_search.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>

namespace st::tune {

class Journal {
public:
    // Reads `file` if it exists, then appends to it.
    explicit Journal(std::filesystem::path file);
    // The measured evaluation of `s` on `views` ("tuned" or "held-out"), if journaled.
    std::optional<Evaluation> find(const Settings& s, const std::string& views) const;
    void add(const Settings& s, const std::string& views, const Evaluation& e);
    std::size_t size() const { return entries_.size(); }
    int ignoredLines() const { return ignored_; }

private:
    std::filesystem::path file_;
    std::ofstream out_;
    std::map<std::string, Evaluation> entries_;  // views + settings text -> evaluation
    int ignored_ = 0;
};

// A short stable id of settings (FNV-1a of their JSON), as sweeps name points.
std::string settingsId(const Settings& s);

}  // namespace st::tune
