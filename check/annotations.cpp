#include "check/annotations.h"

namespace st::check {
namespace {
// A command's message: % CR LF are encoded; a property value also : and ,.
std::string encode(const std::string& s, bool property) {
    std::string out;
    for (char c : s) {
        if (c == '%') out += "%25";
        else if (c == '\r') out += "%0D";
        else if (c == '\n') out += "%0A";
        else if (property && c == ':') out += "%3A";
        else if (property && c == ',') out += "%2C";
        else out += c;
    }
    return out;
}
}  // namespace

std::vector<std::string> githubAnnotations(const std::vector<PresetResult>& results) {
    std::vector<std::string> out;
    for (const PresetResult& r : results) {
        if (!isFailure(r.status)) continue;
        out.push_back("::error file=" + encode(r.preset, true) + ",title=" +
                      encode("shadowtune check: " + r.name + " " + statusName(r.status), true) + "::" + encode(r.message, false));
    }
    return out;
}

}  // namespace st::check
