#include "check/junit_writer.h"

#include "check/markup.h"

#include <cstdio>
#include <sstream>

namespace st::check {
namespace fs = std::filesystem;
namespace {

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", s);
    return text;
}

struct Case {
    std::string classname, name, failureType, message, detail, out;
    double time = 0.0;
};

std::vector<Case> casesOf(const PresetResult& r, const fs::path& reportDir) {
    std::vector<Case> out;
    const std::string cls = "shadowtune.check." + r.name;
    Case preset{cls, r.name, "", "", "", "", r.seconds};
    if (isFailure(r.status)) {
        preset.failureType = statusName(r.status);
        preset.message = std::string(statusName(r.status)) + ": " + r.message;
        preset.detail = "preset " + r.preset + "\n" + r.message;
        for (const std::string& n : r.notes) preset.detail += "\nnote: " + n;
    }
    preset.out = "status " + std::string(statusName(r.status)) + "\n" + r.message;
    if (!r.diffPng.empty() && !reportDir.empty())
        preset.out += "\n[[ATTACHMENT|" + fs::absolute(reportDir / r.diffPng).lexically_normal().string() + "]]";
    out.push_back(preset);
    for (const FigureVerdict& v : r.checks) {
        Case c{cls, r.name + ": " + v.row->key, "", "", "", v.message, 0.0};
        if (!v.pass) {
            c.failureType = "FIGURE_REGRESSION";
            c.message = v.row->key + ": " + v.message;
            c.detail = "preset " + r.preset + "\nrule " + v.rule;
        }
        out.push_back(c);
    }
    return out;
}

}  // namespace

std::string junitXml(const std::string& suiteName, const std::vector<PresetResult>& results, const fs::path& reportDir) {
    std::vector<Case> cases;
    double total = 0.0;
    for (const PresetResult& r : results) {
        total += r.seconds;
        for (Case& c : casesOf(r, reportDir)) cases.push_back(std::move(c));
    }
    std::size_t failures = 0;
    for (const Case& c : cases) failures += c.failureType.empty() ? 0 : 1;
    const std::string name = escapeMarkup(suiteName), n = std::to_string(cases.size()), f = std::to_string(failures);
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites name=\"shadowtune check\" tests=\"" << n << "\" failures=\"" << f << "\" errors=\"0\" time=\""
      << seconds(total) << "\">\n"
      << "  <testsuite name=\"" << name << "\" tests=\"" << n << "\" failures=\"" << f << "\" errors=\"0\" skipped=\"0\" time=\""
      << seconds(total) << "\">\n";
    for (const Case& c : cases) {
        x << "    <testcase classname=\"" << escapeMarkup(c.classname) << "\" name=\"" << escapeMarkup(c.name) << "\" time=\""
          << seconds(c.time) << "\">\n";
        if (!c.failureType.empty())
            x << "      <failure type=\"" << escapeMarkup(c.failureType) << "\" message=\"" << escapeMarkup(c.message) << "\">"
              << escapeMarkup(c.detail) << "</failure>\n";
        if (!c.out.empty()) x << "      <system-out>" << escapeMarkup(c.out) << "</system-out>\n";
        x << "    </testcase>\n";
    }
    x << "  </testsuite>\n</testsuites>\n";
    return x.str();
}

}  // namespace st::check
