// The JUnit XML, the HTML report and annotations: escaping and structure (the XSD and Chromium
// checks of the real files are in check_cli_test.sh).
#include "check/annotations.h"
#include "check/html_report.h"
#include "check/junit_writer.h"
#include "check/markup.h"
#include "check/results_json.h"

#include <gtest/gtest.h>

using namespace st;
using namespace st::check;

namespace {
const std::string kInjected = "<img src=x onerror=alert(1)>";

std::vector<PresetResult> results() {
    PresetResult ok;
    ok.name = "fine";
    ok.preset = "presets/fine.json";
    ok.status = Status::Pass;
    PresetResult bad;
    bad.name = kInjected;
    bad.preset = "presets/" + kInjected + ".json";
    bad.status = Status::Failed;
    bad.note = "a \"quoted\" & <b>bold</b> note";
    FigureTolerance t{&figureNamed("misclassified"), FigureRule::WorseByAtMostPp, 0.05};
    bad.checks = {checkFigure(t, 0.01, 0.02)};
    bad.figures = {{t.row, 0.01, 0.02, bad.checks[0]}};
    bad.message = bad.checks[0].message;
    bad.diffPng = "001-x/diff.png";
    return {ok, bad};
}
}  // namespace

TEST(MarkupTest, EscapesEverythingMarkupReads) {
    EXPECT_EQ(escapeMarkup(kInjected), "&lt;img src=x onerror=alert(1)&gt;");
    EXPECT_EQ(escapeMarkup("a&\"'"), "a&amp;&quot;&#39;");
    EXPECT_EQ(escapeMarkup(std::string("a\x01z")), "a\xEF\xBF\xBDz");
    EXPECT_EQ(safeFileName(3, kInjected), "003-_img_src_x_onerror_alert_1__");
}

TEST(JunitTest, OneCasePerPresetAndFigureWithTheNumbers) {
    const std::string x = junitXml("suite", results(), "/tmp/report");
    EXPECT_NE(x.find("tests=\"3\" failures=\"2\""), std::string::npos) << x;
    EXPECT_NE(x.find("name=\"&lt;img src=x onerror=alert(1)&gt;: accuracy.misclassified\""), std::string::npos) << x;
    EXPECT_NE(x.find("message=\"accuracy.misclassified: misclassified 2.000 % vs golden 1.000 % (+1.000 pp)"),
              std::string::npos) << x;
    EXPECT_NE(x.find("[[ATTACHMENT|/tmp/report/001-x/diff.png]]"), std::string::npos);
    EXPECT_EQ(x.find(kInjected), std::string::npos);
}

TEST(HtmlReportTest, FailuresFirstAndNothingInjected) {
    const std::string h = reportHtml({"suite.json", "g", "llvmpipe", "shadowtune 0.1", false}, results());
    EXPECT_EQ(h.find(kInjected), std::string::npos);
    EXPECT_EQ(h.find("<b>bold"), std::string::npos);
    const auto failed = h.find("data-status=\"FAILED\""), passed = h.find("data-status=\"PASS\"");
    ASSERT_NE(failed, std::string::npos);
    EXPECT_LT(failed, passed);
    EXPECT_EQ(h.find("http://"), std::string::npos);  // no network
    EXPECT_EQ(h.find("https://"), std::string::npos);
}

TEST(AnnotationsTest, OnlyFailuresEscapedForWorkflowCommands) {
    auto r = results();
    r[1].message = "line 1\nline 2, 100%";
    const auto lines = githubAnnotations(r);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0], "::error file=presets/" + kInjected + ".json,title=shadowtune check%3A " + kInjected +
                            " FAILED::line 1%0Aline 2, 100%25");
}

TEST(ResultsJsonTest, CountsAndDeltas) {
    const auto j = resultsJson({"s", "g", "r", "v", false}, results());
    EXPECT_EQ(j["failures"], 1);
    EXPECT_EQ(j["exitCode"], 1);
    EXPECT_EQ(j["results"][1]["name"], kInjected);
    EXPECT_DOUBLE_EQ(j["results"][1]["figures"][0]["delta"].get<double>(), 0.01);
    EXPECT_EQ(j["results"][1]["figures"][0]["check"]["pass"], false);
}
