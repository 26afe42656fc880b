#include "check/html_report.h"

#include "check/markup.h"

#include <sstream>
#include <stdexcept>

namespace st::check {
namespace fs = std::filesystem;
namespace {

const char* kStyle = R"(
body{font:14px/1.4 "DejaVu Sans",sans-serif;margin:1.5em;background:#fafafa;color:#222}
h1{font-size:1.4em;margin:0 0 .3em}
.summary{margin:.3em 0 1em}
#filter{font-size:1em;padding:.3em .5em;width:24em}
section.preset{background:#fff;border:1px solid #ccc;border-left:6px solid #2a2;margin:1em 0;padding:.6em 1em}
section.preset.failure{border-left-color:#d22}
section.preset[hidden]{display:none}
.status{display:inline-block;font-weight:bold;padding:0 .4em;border-radius:3px;color:#fff;background:#2a2}
.failure .status{background:#d22}
h2{font-size:1.15em;margin:.2em 0}
.message{font-family:"DejaVu Sans Mono",monospace;white-space:pre-wrap;margin:.3em 0}
.images{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start}
figure{margin:0}
figcaption{font-size:.85em;color:#555}
.images img{min-width:320px;image-rendering:pixelated}
.slider{position:relative;display:inline-block;line-height:0}
.slider img.top{position:absolute;left:0;top:0;clip-path:inset(0 50% 0 0)}
.slider input{display:block;width:100%}
table{border-collapse:collapse;margin-top:.5em;font-size:.9em}
td,th{border:1px solid #ddd;padding:.15em .5em;text-align:left}
tr.bad td{background:#fdd}
tr.good td.verdict{color:#161}
)";

// The filter hides presets whose name and message do not contain the text (index.html#filter=T
// opens the report filtered); the sliders clip the actual image over the golden one.
// textContent and value only: nothing is parsed as markup.
const char* kScript = R"(
(function(){
  var filter=document.getElementById('filter');
  function apply(){
    var q=filter.value.toLowerCase();
    document.querySelectorAll('section.preset').forEach(function(s){
      s.hidden=q!=='' && s.textContent.toLowerCase().indexOf(q)<0;
    });
  }
  filter.addEventListener('input',apply);
  var m=/^#filter=(.*)$/.exec(location.hash);
  if(m){ filter.value=decodeURIComponent(m[1]); apply(); }
  document.querySelectorAll('.slider').forEach(function(d){
    var top=d.querySelector('img.top'), range=d.querySelector('input');
    function move(){ top.style.clipPath='inset(0 '+(100-range.value)+'% 0 0)'; }
    range.addEventListener('input',move); move();
  });
})();
)";

std::string esc(const std::string& s) { return escapeMarkup(s); }

void figureTable(std::ostringstream& h, const PresetResult& r) {
    h << "<table class=\"figures\"><tr><th>figure</th><th>key</th><th>golden</th><th>actual</th><th>delta</th>"
         "<th>rule</th><th>verdict</th></tr>\n";
    for (const FigureRowResult& f : r.figures) {
        const metrics::FigureUnit u = f.row->unit;
        const std::string delta = f.golden && f.actual ? metrics::formatDelta(u, *f.actual - *f.golden) : "-";
        const char* cls = !f.verdict ? "" : f.verdict->pass ? "good" : "bad";
        h << "<tr class=\"" << cls << "\" data-key=\"" << esc(f.row->key) << "\"><td>" << esc(f.row->label) << "</td><td>"
          << esc(f.row->key) << "</td><td>" << esc(metrics::formatValue(u, f.golden)) << "</td><td>"
          << esc(metrics::formatValue(u, f.actual)) << "</td><td>" << esc(delta) << "</td><td>"
          << (f.verdict ? esc(f.verdict->rule) : "") << "</td><td class=\"verdict\">"
          << (f.verdict ? (f.verdict->pass ? "pass" : "FAIL") : "") << "</td></tr>\n";
    }
    h << "</table>\n";
}

void images(std::ostringstream& h, const PresetResult& r) {
    h << "<div class=\"images\">\n";
    if (!r.goldenPng.empty() && !r.actualPng.empty())
        h << "<figure><div class=\"slider\"><img class=\"bottom\" src=\"" << esc(r.goldenPng) << "\" alt=\"golden\">"
          << "<img class=\"top\" src=\"" << esc(r.actualPng) << "\" alt=\"actual\">"
          << "<input type=\"range\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"actual | golden\"></div>"
          << "<figcaption>left of the slider: actual; right: golden</figcaption></figure>\n";
    if (!r.goldenPng.empty())
        h << "<figure><img src=\"" << esc(r.goldenPng) << "\" alt=\"golden\"><figcaption>golden</figcaption></figure>\n";
    if (!r.actualPng.empty())
        h << "<figure><img src=\"" << esc(r.actualPng) << "\" alt=\"actual\"><figcaption>actual</figcaption></figure>\n";
    if (!r.diffPng.empty())
        h << "<figure><img src=\"" << esc(r.diffPng) << "\" alt=\"diff\"><figcaption>diff (x8; red: over tolerance)"
          << "</figcaption></figure>\n";
    h << "</div>\n";
}

void presetSection(std::ostringstream& h, const PresetResult& r) {
    const bool failure = isFailure(r.status);
    h << "<section class=\"preset" << (failure ? " failure" : "") << "\" data-status=\"" << statusName(r.status) << "\">\n"
      << "<h2><span class=\"status\">" << statusName(r.status) << "</span> <span class=\"name\">" << esc(r.name)
      << "</span></h2>\n"
      << "<div class=\"path\">" << esc(r.preset) << (r.goldenDir.empty() ? "" : " &middot; golden " + esc(r.goldenDir))
      << "</div>\n";
    if (!r.note.empty()) h << "<div class=\"note\">" << esc(r.note) << "</div>\n";
    h << "<div class=\"message\">" << esc(r.message) << "</div>\n";
    for (const std::string& n : r.notes) h << "<div class=\"message\">note: " << esc(n) << "</div>\n";
    if (r.image && r.message.find(r.image->summary()) == std::string::npos) h << "<div class=\"message\">image: " << esc(r.image->summary()) << " (allowed " << esc(r.imageTolerance) << ")</div>\n";
    images(h, r);
    figureTable(h, r);
    h << "</section>\n";
}

}  // namespace

void writePresetImages(const fs::path& reportDir, std::size_t index, PresetResult& r, const Rgba8Image& actual,
                       const Golden* golden, const ImageTolerance& tol) {
    const std::string folder = safeFileName(index, r.name);
    std::error_code ec;
    fs::create_directories(reportDir / folder, ec);
    if (ec) throw std::runtime_error((reportDir / folder).string() + ": cannot create the folder: " + ec.message());
    writeImageAtomic(reportDir / folder / "actual.png", actual);
    r.actualPng = folder + "/actual.png";
    if (!golden) return;
    writeImageAtomic(reportDir / folder / "golden.png", golden->image);
    writeImageAtomic(reportDir / folder / "diff.png", diffPicture(actual, golden->image, tol));
    r.goldenPng = folder + "/golden.png";
    r.diffPng = folder + "/diff.png";
}

std::string reportHtml(const RunInfo& info, const std::vector<PresetResult>& results) {
    const auto ordered = failuresFirst(results);
    std::size_t failures = 0;
    for (const PresetResult* r : ordered) failures += isFailure(r->status) ? 1 : 0;
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      << "<title>shadowtune check: " << esc(fs::path(info.suite).filename().string()) << "</title>\n<style>" << kStyle
      << "</style></head><body>\n"
      << "<h1>shadowtune check: " << esc(info.suite) << "</h1>\n"
      << "<div class=\"summary\" id=\"summary\">" << failures << " of " << results.size() << " presets failed"
      << (info.update ? " (--update)" : "") << " &middot; golden " << esc(info.golden) << " &middot; renderer "
      << esc(info.renderer) << " &middot; " << esc(info.version) << "</div>\n"
      << "<input id=\"filter\" type=\"search\" placeholder=\"filter presets by name or message\">\n<main id=\"presets\">\n";
    for (const PresetResult* r : ordered) presetSection(h, *r);
    h << "</main>\n<script>" << kScript << "</script>\n</body></html>\n";
    return h.str();
}

void writeReport(const fs::path& reportDir, const RunInfo& info, const std::vector<PresetResult>& results) {
    std::error_code ec;
    fs::create_directories(reportDir, ec);
    if (ec || !fs::is_directory(reportDir))
        throw std::runtime_error(reportDir.string() + ": cannot create the report folder: " + (ec ? ec.message() : "not a folder"));
    writeTextAtomic(reportDir / "index.html", reportHtml(info, results));
    writeTextAtomic(reportDir / "results.json", resultsJson(info, results).dump(2) + "\n");
}

}  // namespace st::check
