#pragma once
// The tune's journal: every evaluation made, one JSON line each, appended and flushed as soon as
// it is measured, so Ctrl-C (or a crash) keeps them and the same command resumes without measuring
// them again. A line cut short by a kill is ignored on reading. No GL.
//
// A sharded tune (`--shard k/n`, docs/tuning.md#shards) runs one process per shard on one shared
// folder: each appends to its own file and reads the others' as they grow, so every shard's search
// sees every measurement. A later run over the folder reads them all (the merge).
#include "renderer/settings/settings.h"
#include "tune/tune_search.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace st::tune {

// Shard `index` of `count`, 1-based as `--shard 2/4` reads; {1, 1} is an unsharded tune.
struct Shard {
    int index = 1;
    int count = 1;
    bool sharded() const { return count > 1; }
};

class Journal {
public:
    // Reads every journal in `dir` (evaluations*.jsonl), then appends to this shard's own.
    Journal(std::filesystem::path dir, Shard shard);
    // The measured evaluation of `s` on `views` ("tuned", "held-out", "screen"), if journaled.
    std::optional<Evaluation> find(const Settings& s, const std::string& views) const;
    void add(const Settings& s, const std::string& views, const Evaluation& e);
    // Reads what other shards appended since the last call (complete lines only); how many new.
    int refresh();
    std::size_t size() const { return entries_.size(); }
    int ignoredLines() const { return ignored_; }
    const std::filesystem::path& file() const { return own_; }

private:
    struct Source {
        std::filesystem::path file;
        std::streamoff read = 0;  // bytes consumed: up to the last complete line
    };
    int readNew(Source& src, bool last);
    void take(const std::string& line);

    std::filesystem::path dir_, own_;
    std::ofstream out_;
    std::vector<Source> others_;
    std::map<std::string, Evaluation> entries_;  // views + settings text -> evaluation
    int ignored_ = 0;
};

// The journal file of a shard: evaluations.jsonl, or evaluations.shard-K-of-N.jsonl.
std::string journalName(Shard shard);

// Which shard measures `s` on `views` when no shard has yet: a hash of both, so every shard agrees
// without talking and the work spreads evenly.
int ownerOf(const Settings& s, const std::string& views, int count);

// A short stable id of settings (FNV-1a of their JSON), as sweeps name points.
std::string settingsId(const Settings& s);

}  // namespace st::tune
