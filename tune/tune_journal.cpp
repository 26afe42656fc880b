#include "tune/tune_journal.h"

#include "renderer/settings/settings_json.h"
#include "tune/tune_eval.h"

#include <cstdint>
#include <cstdio>

namespace st::tune {
namespace {
std::string keyOf(const std::string& views, const std::string& settingsText) { return views + "\n" + settingsText; }
}  // namespace

std::string settingsId(const Settings& s) {
    std::uint64_t h = 1469598103934665603ull;
    for (const char c : toOrderedJson(s).dump()) h = (h ^ std::uint8_t(c)) * 1099511628211ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

Journal::Journal(std::filesystem::path file) : file_(std::move(file)) {
    if (std::ifstream in(file_); in) {
        std::string line;
        while (std::getline(in, line)) {
            try {
                const auto j = nlohmann::ordered_json::parse(line);
                entries_[keyOf(j.at("views").get<std::string>(), j.at("settings").dump())] = evaluationFromJson(j.at("evaluation"));
            } catch (const nlohmann::json::exception&) {
                ++ignored_;  // cut short by a kill mid-write: measured again
            }
        }
    }
    out_.open(file_, std::ios::app);
    if (!out_) throw std::runtime_error(file_.string() + ": cannot write the tune's journal");
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
    if (!out_) throw std::runtime_error(file_.string() + ": cannot append to the tune's journal");
}

}  // namespace st::tune
