// The interface header's C++ side, the field table's `.shader` column and the shader library's
// #include expansion, without a GL context.
#include "renderer/csm/cascade_plan.h"
#include "renderer/render/shader_blocks.h"
#include "renderer/render/shader_library.h"
#include "renderer/settings/field_table.h"

#include <gtest/gtest.h>

#include <map>
#include <span>
#include <string>
#include <vector>

using namespace st;

namespace {
struct NamedMember {
    std::string_view block;
    gpu_if::MemberInfo info;
};

template <class Block>
void collect(std::vector<NamedMember>& out) {
    for (const gpu_if::MemberInfo& m : gpu_if::BlockMembers<Block>::members)
        if (!m.name.empty()) out.push_back({gpu_if::BlockMembers<Block>::blockName, m});
}

// Members of the blocks GLSL sees as global names (CascadeData's are reached through `cascade`).
std::vector<NamedMember> globalMembers() {
    std::vector<NamedMember> all;
    collect<gpu_if::FrameBlock>(all);
    collect<gpu_if::ViewBlock>(all);
    collect<gpu_if::CascadeBlock>(all);
    collect<gpu_if::MaterialBlock>(all);
    collect<gpu_if::OverlayBlock>(all);
    return all;
}

Settings twoCascades() {
    Settings s;
    s.cascades.count = 2;
    s.cascades.blendBand = 0.37f;
    s.filter.kind = FilterKind::PcfNxN;
    s.filter.size = 5;
    s.bias.receiverPlane = true;
    s.bias.slope = 2.5f;
    s.light.ambient = 0.2f;
    s.output.view = View::TexelDensity;
    return s;
}
}  // namespace

TEST(ShaderInterfaceTest, BlockMemberNamesAreUniqueGlobals) {
    std::map<std::string_view, std::string_view> seen;
    for (const NamedMember& m : globalMembers()) {
        auto [it, fresh] = seen.emplace(m.info.name, m.block);
        EXPECT_TRUE(fresh) << m.info.name << " is a member of both " << it->second << " and " << m.block;
    }
}

TEST(ShaderInterfaceTest, EveryShaderFieldNamesOneMemberOfItsType) {
    int fed = 0;
    for (const FieldInfo& field : fieldTable()) {
        if (field.shader.empty()) continue;
        ++fed;
        int found = 0;
        for (const NamedMember& m : globalMembers()) {
            if (m.info.name != field.shader) continue;
            ++found;
            const auto want = field.kind == FieldKind::Float ? gpu_if::MemberType::Float : gpu_if::MemberType::Int;
            EXPECT_EQ(m.info.type, want) << field.path << " -> " << m.block << "::" << m.info.name;
            EXPECT_TRUE(field.kind == FieldKind::Float || field.kind == FieldKind::Int ||
                        field.kind == FieldKind::Bool || field.kind == FieldKind::Enum)
                << field.path;
        }
        EXPECT_EQ(found, 1) << field.path << " names shader member '" << field.shader << "'";
    }
    EXPECT_GE(fed, 10);  // the shading knobs: light, cascades, filter, bias, view
}

TEST(ShaderInterfaceTest, BlocksCarryTheSettingsAndThePlan) {
    const Settings s = twoCascades();
    const csm::CascadePlan plan = csm::planCascades(s, 16.0f / 9.0f, csm::Aabb{{-10, 0, -10}, {10, 5, 10}});
    const gpu_if::CascadeBlock c = cascadeBlock(s, plan);
    EXPECT_EQ(c.cascadeCount, 2);
    EXPECT_FLOAT_EQ(c.blendBand, 0.37f);
    EXPECT_EQ(c.filterKind, ST_FILTER_PCF_NXN);
    EXPECT_EQ(c.filterSize, 5);
    EXPECT_EQ(c.receiverPlane, 1);
    EXPECT_FLOAT_EQ(c.biasSlope, 2.5f);
    EXPECT_EQ(c.storage, ST_STORAGE_ARRAY);
    EXPECT_EQ(c.selection, ST_SELECT_INTERVAL);
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(c.cascade[i].vsNear, plan.splits[std::size_t(i)]);
        EXPECT_EQ(c.cascade[i].vsFar, plan.splits[std::size_t(i) + 1]);
        EXPECT_EQ(c.cascade[i].texelWorld, plan.cascades[std::size_t(i)].texelWorldSize);
        EXPECT_EQ(c.cascade[i].layer, i);  // array: layer i, the whole layer, 1/mapSize per texel
        EXPECT_EQ(c.cascade[i].tileBounds, glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
        EXPECT_FLOAT_EQ(c.cascade[i].uvPerTexel.x, 1.0f / float(s.cascades.mapSize));
    }
    const gpu_if::FrameBlock f = frameBlock(s, plan);
    EXPECT_FLOAT_EQ(f.ambient, 0.2f);
    EXPECT_EQ(f.viewMode, ST_VIEW_TEXEL_DENSITY);
    EXPECT_FLOAT_EQ(f.wsToSun.y, -plan.wsLightDir.y);
}

TEST(ShaderInterfaceTest, AFieldNamingAMemberOfAnotherTypeIsAProgrammingError) {
    // "cascadeCount" is an int member; feed it from a float field through a fake member table.
    const gpu_if::MemberInfo wrong[] = {{"blendBand", 0, sizeof(int), gpu_if::MemberType::Int}};
    int block = 0;
    Settings s;
    s.cascades.blendBand = 0.25f;
    EXPECT_THROW(copyShaderFields(s, std::span(wrong), &block), std::logic_error);
}

TEST(ShaderLibraryTest, IncludesAreInlinedBetweenLineDirectives) {
    const ShaderSources sources = {{"a.frag", "#version 450 core\n#include \"b.glsl\"\nvoid main() {}\n"},
                                   {"b.glsl", "float f;\n#include \"c.glsl\"\nfloat g;\n"},
                                   {"c.glsl", "float h;\n"}};
    const ExpandedShader e = expandShader("a.frag", sources);
    EXPECT_EQ(e.text,
              "#version 450 core\n#line 100001 1\nfloat f;\n#line 200001 2\nfloat h;\n#line 100003 1\nfloat g;\n#line 3 0\n"
              "void main() {}\n");
    EXPECT_EQ(e.files, (std::vector<std::string>{"a.frag", "b.glsl", "c.glsl"}));
}

TEST(ShaderLibraryTest, UnknownIncludeAndRecursionAreReported) {
    EXPECT_THROW(expandShader("x.frag", {{"x.frag", "#include \"missing.glsl\"\n"}}), std::runtime_error);
    EXPECT_THROW(expandShader("loop.glsl", {{"loop.glsl", "#include \"loop.glsl\"\n"}}), std::runtime_error);
}

TEST(ShaderLibraryTest, LogSourceNumbersBecomeFileNames) {
    const std::vector<std::string> files = {"main.frag", "shadow_sampling.glsl"};
    // The line range says the file, even where the driver dropped the source-string number.
    EXPECT_EQ(nameLogFiles("1:100012(5): error: `x' undeclared\n0:3(1): error: syntax error\n", files),
              "shadow_sampling.glsl:12(5): error: `x' undeclared\nmain.frag:3(1): error: syntax error\n");
    EXPECT_EQ(nameLogFiles("0:100012(9): error: `x' undeclared", files), "shadow_sampling.glsl:12(9): error: `x' undeclared");
    EXPECT_EQ(nameLogFiles("ERROR: 1:100007: 'y' : undeclared identifier", files),
              "ERROR: shadow_sampling.glsl:7: 'y' : undeclared identifier");
    EXPECT_EQ(nameLogFiles("9:900001(1): error: out of range", files), "9:900001(1): error: out of range");
}

TEST(ShaderLibraryTest, EveryEmbeddedShaderExpands) {
    for (const auto& [name, text] : embeddedShaders()) {
        if (!name.ends_with(".vert") && !name.ends_with(".frag")) continue;
        const ExpandedShader e = expandShader(name);
        EXPECT_EQ(e.text.rfind("#version 450 core\n", 0), 0u) << name;
        EXPECT_EQ(e.text.find("#include \""), std::string::npos) << name;
    }
}
