// The tune's journal, as shards share it: another shard's lines are read as they are appended,
// a line still being written is not, a line cut short by a kill costs only itself, and every
// shard agrees on who measures a point without talking. No GL.
#include "tune/tune_journal.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>

namespace st::tune {
namespace {
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() / ("st_journal_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

Settings withLambda(float l) {
    Settings s;
    s.cascades.lambda = l;
    return s;
}

// The journal keeps the raw figures (the objective is judged from them on reading).
Evaluation withError(double e) {
    Evaluation v;
    v.figures["accuracy.misclassified"] = e;
    return v;
}

double misclassified(const std::optional<Evaluation>& e) { return e->figures.at("accuracy.misclassified").get<double>(); }

TEST(TuneJournalTest, AShardReadsAnotherShardsLinesAsTheyAreAppended) {
    const fs::path dir = freshDir("share");
    Journal one(dir, {1, 2});
    Journal two(dir, {2, 2});
    one.add(withLambda(0.5f), "tuned", withError(0.25));
    EXPECT_FALSE(two.find(withLambda(0.5f), "tuned")) << "read only on refresh";
    EXPECT_EQ(two.refresh(), 1);
    ASSERT_TRUE(two.find(withLambda(0.5f), "tuned"));
    EXPECT_DOUBLE_EQ(misclassified(two.find(withLambda(0.5f), "tuned")), 0.25);
    EXPECT_FALSE(two.find(withLambda(0.5f), "screen")) << "views are part of the key";
    EXPECT_EQ(two.refresh(), 0) << "nothing new";
    EXPECT_TRUE(fs::exists(dir / "evaluations.shard-1-of-2.jsonl"));
    EXPECT_TRUE(fs::exists(dir / "evaluations.shard-2-of-2.jsonl"));
}

TEST(TuneJournalTest, ALineStillBeingWrittenIsReadOnlyOnceComplete) {
    const fs::path dir = freshDir("partial");
    Journal reader(dir, {2, 2});
    std::string line;
    {
        Journal writer(freshDir("partial_src"), {1, 1});
        writer.add(withLambda(0.7f), "tuned", withError(0.5));
        std::ifstream in(writer.file());
        std::getline(in, line);
    }
    std::ofstream peer(dir / "evaluations.shard-1-of-2.jsonl", std::ios::binary);
    peer << line.substr(0, line.size() / 2) << std::flush;
    EXPECT_EQ(reader.refresh(), 0);
    EXPECT_EQ(reader.ignoredLines(), 0) << "half a line is waited for, not thrown away";
    peer << line.substr(line.size() / 2) << "\n" << std::flush;
    EXPECT_EQ(reader.refresh(), 1);
    EXPECT_TRUE(reader.find(withLambda(0.7f), "tuned"));
}

TEST(TuneJournalTest, ALineCutShortByAKillCostsOnlyItself) {
    const fs::path dir = freshDir("cut");
    {
        Journal j(dir, {1, 1});
        j.add(withLambda(0.5f), "tuned", withError(0.1));
    }
    std::ofstream(dir / "evaluations.jsonl", std::ios::app) << R"({"id":"x","views":"tuned","evalu)";
    {
        Journal j(dir, {1, 1});
        EXPECT_EQ(j.ignoredLines(), 1);
        EXPECT_EQ(j.size(), 1u);
        j.add(withLambda(0.6f), "tuned", withError(0.2));  // starts on a line of its own
    }
    Journal j(dir, {1, 1});
    EXPECT_EQ(j.size(), 2u);
    ASSERT_TRUE(j.find(withLambda(0.6f), "tuned"));
    EXPECT_DOUBLE_EQ(misclassified(j.find(withLambda(0.6f), "tuned")), 0.2);
}

TEST(TuneJournalTest, ShardsAgreeOnOwnersAndShareTheWorkEvenly) {
    std::map<int, int> count;
    for (int i = 0; i < 300; ++i) {
        const Settings s = withLambda(0.001f * float(i));
        const int owner = ownerOf(s, "tuned", 3);
        ASSERT_GE(owner, 1);
        ASSERT_LE(owner, 3);
        EXPECT_EQ(owner, ownerOf(s, "tuned", 3)) << "the same answer every time";
        ++count[owner];
    }
    for (int k = 1; k <= 3; ++k) EXPECT_GT(count[k], 70) << "shard " << k << " of 3 gets about a third of 300";
    EXPECT_EQ(ownerOf(withLambda(0.5f), "tuned", 1), 1);
    EXPECT_EQ(journalName({1, 1}), "evaluations.jsonl");
    EXPECT_EQ(journalName({3, 4}), "evaluations.shard-3-of-4.jsonl");
}

}  // namespace
}  // namespace st::tune
