// The include check fails where it must: on a synthetic tree with planted upward includes, and on
// the real tree with a table that forbids what the tree includes. The real tree against the real
// table is the CTest LayerIncludesTest.SourceTree.
#include "tests/layers/layer_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>

namespace st::layers {
namespace {
namespace fs = std::filesystem;

const fs::path kRoot = ST_SOURCE_DIR;

// A tree with one file in each layer of threeLayers(), which tests overwrite or add to.
class TempTree {
public:
    TempTree() : root_(fs::temp_directory_path() / ("st_layers_test_" + std::to_string(std::random_device{}()))) {
        fs::create_directories(root_);
        write("low/x.h", "#pragma once\n");
        write("mid/m.h", "#pragma once\n");
        write("high/a.cpp", "\n");
    }
    ~TempTree() {
        std::error_code ec;
        fs::remove_all(root_, ec);
    }
    void write(const std::string& rel, const std::string& text) const {
        fs::create_directories((root_ / rel).parent_path());
        std::ofstream(root_ / rel) << text;
    }
    const fs::path& root() const { return root_; }

private:
    fs::path root_;
};

std::vector<std::string> texts(const std::vector<Violation>& violations) {
    std::vector<std::string> out;
    for (const auto& v : violations) out.push_back(v.text());
    return out;
}

bool anyContains(const std::vector<std::string>& lines, const std::string& part) {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

// A line starting with `file` (then its line number) that holds `rule`: real files move lines.
bool anyAt(const std::vector<std::string>& lines, const std::string& file, const std::string& rule) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& l) { return l.rfind(file + ":", 0) == 0 && l.find(rule) != std::string::npos; });
}

// low <- mid <- high; mid only from high/a.cpp.
Table threeLayers() {
    Table t;
    t.scanned = {"low", "mid", "high", "other"};
    t.everywhere = {"unistd.h"};
    t.layers = {
        {"low", {"low/"}, "bottom", "st_low", {}, {{"glm/", {}}}},
        {"mid", {"mid/"}, "middle", "st_mid", {{"low", {}}}, {}},
        {"high", {"high/"}, "top", "st_high", {{"low/x.h", {}}, {"mid", {"high/a.cpp"}}}, {{"epoxy/", {"high/a.cpp"}}}},
    };
    return t;
}

TEST(LayersTest, AllowedIncludesPass) {
    TempTree tree;
    tree.write("low/x.h", "#pragma once\n#include <vector>\n#include <glm/vec3.hpp>\n#include <unistd.h>\n");
    tree.write("low/x.cpp", "#include \"low/x.h\"\n");
    tree.write("mid/m.h", "#include \"low/x.h\"\n");
    tree.write("high/a.cpp", "#include \"low/x.h\"\n  #  include \"mid/m.h\"\n#include <epoxy/gl.h>\n");
    EXPECT_EQ(texts(checkTree(threeLayers(), tree.root())), std::vector<std::string>{});
}

TEST(LayersTest, UpwardIncludeFailsWithFileLineAndRule) {
    TempTree tree;
    tree.write("high/a.h", "#pragma once\n");
    tree.write("low/x.h", "#pragma once\n\n#include \"high/a.h\"\n");
    const auto v = texts(checkTree(threeLayers(), tree.root()));
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0], "low/x.h:3: #include \"high/a.h\": layer \"low\" may not include high/a.h (layer \"high\"); it may include nothing");
}

TEST(LayersTest, FileOfALayerNotNamedFails) {
    TempTree tree;
    tree.write("low/x.h", "#pragma once\n");
    tree.write("low/y.h", "#pragma once\n");
    tree.write("high/b.cpp", "#include \"low/y.h\"\n");  // high may include low/x.h only
    const auto v = texts(checkTree(threeLayers(), tree.root()));
    ASSERT_EQ(v.size(), 1u);
    EXPECT_TRUE(anyContains(v, "high/b.cpp:1: #include \"low/y.h\": layer \"high\" may not include low/y.h (layer \"low\")")) << v[0];
}

TEST(LayersTest, UseLimitedToSomeFilesFailsElsewhere) {
    TempTree tree;
    tree.write("mid/m.h", "#pragma once\n");
    tree.write("high/a.cpp", "#include \"mid/m.h\"\n#include <epoxy/gl.h>\n");
    tree.write("high/b.cpp", "#include \"mid/m.h\"\n#include <epoxy/gl.h>\n");
    const auto v = texts(checkTree(threeLayers(), tree.root()));
    ASSERT_EQ(v.size(), 2u);
    EXPECT_TRUE(anyContains(v, "high/b.cpp:1: #include \"mid/m.h\": layer \"high\" may not include mid/m.h (layer \"mid\") from this file"));
    EXPECT_TRUE(anyContains(v, "high/b.cpp:2: #include <epoxy/gl.h>: layer \"high\" may not include the library header epoxy/gl.h from this file"));
}

TEST(LayersTest, LibraryNotListedFails) {
    TempTree tree;
    tree.write("mid/m.cpp", "#include <vector>\n#include <GLFW/glfw3.h>\n#include \"generated.h\"\n");
    const auto v = texts(checkTree(threeLayers(), tree.root()));
    ASSERT_EQ(v.size(), 2u);
    EXPECT_TRUE(anyContains(v, "mid/m.cpp:2: #include <GLFW/glfw3.h>: layer \"mid\" may not include the library header GLFW/glfw3.h"));
    EXPECT_TRUE(anyContains(v, "mid/m.cpp:3: #include \"generated.h\": layer \"mid\" may not include the library header generated.h"));
}

TEST(LayersTest, GlCallOutsideTheRendererFails) {
    TempTree tree;
    tree.write("high/a.cpp", "void f() {\n"
                             "    glfwInit();  // glFinish() in a comment\n"
                             "    auto v = glm::vec3(1); puts(\"glClear(\");\n"
                             "    glBlitNamedFramebuffer (1, 0);\n"
                             "}\n");
    tree.write("low/x.cpp", "void g() { glFinish(); }\n");
    Table t = threeLayers();
    t.layers[0].glCalls = true;
    const auto v = texts(checkTree(t, tree.root()));
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0], "high/a.cpp:4: layer \"high\" makes the GL call glBlitNamedFramebuffer(); GL calls belong to the renderer (a layer with \"gl_calls\": true)");
}

TEST(LayersTest, FileNoLayerOwnsFails) {
    TempTree tree;
    tree.write("other/z.cpp", "int z;\n");
    tree.write("other/notes.txt", "not a source file\n");
    const auto v = texts(checkTree(threeLayers(), tree.root()));
    ASSERT_EQ(v.size(), 1u);
    EXPECT_TRUE(anyContains(v, "other/z.cpp:0: no layer owns this file"));
}

TEST(LayersTest, StaleTableEntriesFail) {
    TempTree tree;
    tree.write("low/x.h", "#pragma once\n");
    Table t = threeLayers();
    t.layers[0].files.push_back("low/gone.h");
    t.layers[2].mayInclude.push_back({"nowhere/", {}});
    const auto v = texts(checkTree(t, tree.root()));
    EXPECT_TRUE(anyContains(v, "layer \"low\" owns low/gone.h, which does not exist"));
    EXPECT_TRUE(anyContains(v, "layer \"high\" may include \"nowhere/\", which is neither a layer nor a file"));
}

TEST(LayersTest, NamedFileBeatsFolderAndDeeperFolderBeatsShallower) {
    Table t;
    t.layers = {{"a", {"r/"}, "", "", {}, {}}, {"b", {"r/s/"}, "", "", {}, {}}, {"c", {"r/s/x.h"}, "", "", {}, {}}};
    EXPECT_EQ(owner(t, "r/y.h")->name, "a");
    EXPECT_EQ(owner(t, "r/s/y.h")->name, "b");
    EXPECT_EQ(owner(t, "r/s/x.h")->name, "c");
    EXPECT_EQ(owner(t, "q/x.h"), nullptr);
    EXPECT_EQ(owner(t, "rr/x.h"), nullptr);
}

// The real tree fails the real table once a permission it relies on is withdrawn.
TEST(LayersTest, RealTreeFailsATableThatForbidsWhatItIncludes) {
    Table t = loadTable(kRoot / "docs/layers.json");
    ASSERT_EQ(texts(checkTree(t, kRoot)), std::vector<std::string>{});
    for (Layer& l : t.layers) {
        if (l.name == "renderer/gpu") l.external.clear();  // the GL loader
        if (l.name == "renderer/csm") l.mayInclude.clear();  // settings.h
        if (l.name == "renderer/render") l.glCalls = false;
    }
    const auto v = texts(checkTree(t, kRoot));
    EXPECT_TRUE(anyAt(v, "renderer/gpu/gl.h", "#include <epoxy/gl.h>: layer \"renderer/gpu\" may not include the library header epoxy/gl.h"));
    EXPECT_TRUE(anyAt(v, "renderer/csm/splits.h", "#include \"renderer/settings/settings.h\": layer \"renderer/csm\" may not include"));
    EXPECT_TRUE(anyAt(v, "renderer/render/present.cpp", "layer \"renderer/render\" makes the GL call glBlitNamedFramebuffer()"));
}

TEST(LayersTest, TableErrorsNameTheJsonPath) {
    TempTree tree;
    tree.write("t.json", R"({"scanned": ["a"], "layers": [{"name": "a", "files": ["a/"], "role": "", "target": "", "may_include": [3]}]})");
    try {
        loadTable(tree.root() / "t.json");
        FAIL() << "a malformed table loaded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("t.json: /layers/0/may_include/0: expected a string"), std::string::npos) << e.what();
    }
    tree.write("u.json", R"({"scanned": ["a"], "layers": [{"name": "a", "files": ["a/"], "role": "", "target": "", "may_inlcude": []}]})");
    try {
        loadTable(tree.root() / "u.json");
        FAIL() << "a table with a misspelt key loaded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("u.json: /layers/0/may_inlcude: unknown key"), std::string::npos) << e.what();
    }
}

TEST(LayersTest, DocTableIsReplacedBetweenTheMarkers) {
    const Table t = threeLayers();
    const std::string doc = std::string("intro\n") + kDocBegin + "\nold table\n" + kDocEnd + "\nafter\n";
    const std::string updated = withTable(doc, t);
    EXPECT_EQ(updated, std::string("intro\n") + kDocBegin + "\n" + markdownTable(t) + kDocEnd + "\nafter\n");
    EXPECT_EQ(withTable(updated, t), updated);
    EXPECT_NE(markdownTable(t).find("| **high** | `high/` | top | `low/x.h`, `mid` (from `high/a.cpp` only) | `epoxy/` (from `high/a.cpp` only) | no | st_high |"),
              std::string::npos)
        << markdownTable(t);
    EXPECT_THROW(withTable("no markers\n", t), std::runtime_error);
}

TEST(LayersTest, DiagramMustNameEveryLayer) {
    const Table t = threeLayers();
    const std::string doc = "## Layers\n\n```\nhigh/\n  |-> low/   the bottom\n  |-> low/mid x\n```\nmid\n";
    // "mid" appears only inside a path and after the diagram: it is missing.
    EXPECT_EQ(missingFromDiagram(doc, t), std::vector<std::string>{"mid"});
}

}  // namespace
}  // namespace st::layers
