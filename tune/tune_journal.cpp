#include "tune/tune_journal.h"

#include "renderer/settings/settings_json.h"
#include "tune/tune_eval.h"

#include <cstdint>
#include <cstdio>

namespace st::tune {
namespace fs = std::filesystem;
namespace {

std::string keyOf(const std::string& views, const std::string& settingsText) { return views + "\n" + settingsText; }

std::uint64_t fnv1a(const std::string& text, std::uint64_t h = 1469598103934665603ull) {
    for (const char c : text) h = (h ^ std::uint8_t(c)) * 1099511628211ull;
    return h;
}

bool isJournal(const fs::path& p) {
    const std::string name = p.filename().string();
    return name.rfind("evaluations", 0) == 0 && p.extension() == ".jsonl";
}

}  // namespace

std::string journalName(Shard shard) {
    if (!shard.sharded()) return "evaluations.jsonl";
    return "evaluations.shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".jsonl";
}

int ownerOf(const Settings& s, const std::string& views, int count) {
    if (count <= 1) return 1;
    return int(fnv1a(toOrderedJson(s).dump(), fnv1a(views)) % std::uint64_t(count)) + 1;
}

std::string settingsId(const Settings& s) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(fnv1a(toOrderedJson(s).dump())));
    return text;
}

Journal::Journal(fs::path dir, Shard shard) : dir_(std::move(dir)), own_(dir_ / journalName(shard)) {
    Source own{own_};
    readNew(own, true);  // our own file: a line cut short by a kill is measured again
    refresh();
    out_.open(own_, std::ios::app);
    if (!out_) throw std::runtime_error(own_.string() + ": cannot write the tune's journal");
    // A line cut short by a kill: the next one starts on a line of its own, or both are lost.
    if (std::ifstream last(own_, std::ios::binary | std::ios::ate); last && last.tellg() > 0) {
        last.seekg(-1, std::ios::end);
        if (last.get() != '\n') out_ << '\n' << std::flush;
    }
}

void Journal::take(const std::string& line) {
    try {
        const auto j = nlohmann::ordered_json::parse(line);
        entries_[keyOf(j.at("views").get<std::string>(), j.at("settings").dump())] = evaluationFromJson(j.at("evaluation"));
    } catch (const nlohmann::json::exception&) {
        ++ignored_;  // cut short by a kill mid-write: measured again
    }
}

// Reads src from where it stopped. A line with no newline yet may still be being written by
// another shard: it is read next time, unless this is the last read (`last`) of a finished file.
int Journal::readNew(Source& src, bool last) {
    std::ifstream in(src.file, std::ios::binary);
    if (!in) return 0;
    in.seekg(src.read);
    std::string chunk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    int added = 0;
    std::size_t start = 0;
    for (std::size_t nl; (nl = chunk.find('\n', start)) != std::string::npos; start = nl + 1) {
        if (nl > start) {
            take(chunk.substr(start, nl - start));
            ++added;
        }
    }
    if (last && start < chunk.size()) {
        take(chunk.substr(start));
        start = chunk.size();
    }
    src.read += std::streamoff(start);
    return added;
}

int Journal::refresh() {
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir_, ec)) {
        if (!isJournal(e.path()) || e.path() == own_) continue;
        bool known = false;
        for (const Source& s : others_) known = known || s.file == e.path();
        if (!known) others_.push_back({e.path()});
    }
    int added = 0;
    for (Source& s : others_) added += readNew(s, false);
    return added;
}

std::optional<Evaluation> Journal::find(const Settings& s, const std::string& views) const {
    const auto it = entries_.find(keyOf(views, toOrderedJson(s).dump()));
    if (it == entries_.end()) return std::nullopt;
    return it->second;
}

void Journal::add(const Settings& s, const std::string& views, const Evaluation& e) {
    const nlohmann::ordered_json settings = toOrderedJson(s);
    entries_[keyOf(views, settings.dump())] = e;
    const nlohmann::ordered_json line = {{"id", settingsId(s)}, {"views", views}, {"evaluation", toJson(e)}, {"settings", settings}};
    out_ << line.dump() << "\n" << std::flush;
    if (!out_) throw std::runtime_error(own_.string() + ": cannot append to the tune's journal");
}

}  // namespace st::tune
