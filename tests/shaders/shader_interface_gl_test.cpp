// The C++ structs of shaders/interface.h against the driver's std140 layout of the same blocks,
// and compile errors that name the included file and line.
#include "renderer/render/shader_library.h"
#include "shaders/interface.h"
#include "tests/support/gl_fixture.h"

#include <gtest/gtest.h>

#include <string>

using namespace st;

namespace {
class ShaderInterfaceGLTest : public test::GLTest {};

// A fragment shader that reads one member of every block, so each block is active.
const char* kProbe = R"(#version 450 core
#include "interface.h"
out vec4 o;
void main() {
    o = view[0] + wsToSun + viewProj[1] + cascade[1].tint + baseColor
      + vec4(brightness + float(cascadeCount) + float(reduceMode) + float(screenShadow) + float(screenRadius));
}
)";

ShaderSources probeSources() {
    ShaderSources sources = embeddedShaders();
    sources["probe.frag"] = kProbe;
    return sources;
}

GLint resource(GLuint program, const std::string& name, GLenum property) {
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, name.c_str());
    EXPECT_NE(index, GL_INVALID_INDEX) << name << " is not an active uniform";
    if (index == GL_INVALID_INDEX) return -1;
    GLint value = -1;
    glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &property, 1, nullptr, &value);
    return value;
}

GLint blockSize(GLuint program, const char* block) {
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM_BLOCK, block);
    EXPECT_NE(index, GL_INVALID_INDEX) << block;
    const GLenum property = GL_BUFFER_DATA_SIZE;
    GLint value = -1;
    glGetProgramResourceiv(program, GL_UNIFORM_BLOCK, index, 1, &property, 1, nullptr, &value);
    return value;
}

template <class Block>
void expectLayout(GLuint program, const std::string& prefix = "", std::size_t base = 0) {
    for (const gpu_if::MemberInfo& m : gpu_if::BlockMembers<Block>::members) {
        if (m.name.empty() || m.type == gpu_if::MemberType::Other) continue;
        EXPECT_EQ(resource(program, prefix + std::string(m.name), GL_OFFSET), GLint(base + m.offset))
            << gpu_if::BlockMembers<Block>::blockName << "::" << m.name;
    }
}
}  // namespace

TEST_F(ShaderInterfaceGLTest, CppStructsMatchTheDriversStd140Layout) {
    const gpu::Program p = linkShaderFiles("fullscreen.vert", "probe.frag", "probe", probeSources());
    expectLayout<gpu_if::FrameBlock>(p.id());
    expectLayout<gpu_if::CascadeBlock>(p.id());
    expectLayout<gpu_if::MaterialBlock>(p.id());
    expectLayout<gpu_if::OverlayBlock>(p.id());
    expectLayout<gpu_if::ReduceBlock>(p.id());
    expectLayout<gpu_if::ViewBlock>(p.id());
    expectLayout<gpu_if::ScreenBlock>(p.id());
    for (const char* m : {"view", "viewProj"}) EXPECT_EQ(resource(p.id(), m, GL_MATRIX_STRIDE), 16) << m;
    EXPECT_EQ(resource(p.id(), "viewProj", GL_OFFSET), 0);
    // The struct array: each element where C++ puts it, matrices column-major like GLM's.
    const std::size_t first = offsetof(gpu_if::CascadeBlock, cascade);
    expectLayout<gpu_if::CascadeData>(p.id(), "cascade[0].", first);
    expectLayout<gpu_if::CascadeData>(p.id(), "cascade[7].", first + 7 * sizeof(gpu_if::CascadeData));
    EXPECT_EQ(resource(p.id(), "cascade[3].shadowMatrix", GL_OFFSET),
              GLint(first + 3 * sizeof(gpu_if::CascadeData) + offsetof(gpu_if::CascadeData, shadowMatrix)));
    EXPECT_EQ(resource(p.id(), "cascade[0].shadowMatrix", GL_IS_ROW_MAJOR), 0);
    EXPECT_EQ(blockSize(p.id(), "FrameBlock"), GLint(sizeof(gpu_if::FrameBlock)));
    EXPECT_EQ(blockSize(p.id(), "ViewBlock"), GLint(sizeof(gpu_if::ViewBlock)));
    EXPECT_EQ(blockSize(p.id(), "CascadeBlock"), GLint(sizeof(gpu_if::CascadeBlock)));
    EXPECT_EQ(blockSize(p.id(), "MaterialBlock"), GLint(sizeof(gpu_if::MaterialBlock)));
    EXPECT_EQ(blockSize(p.id(), "OverlayBlock"), GLint(sizeof(gpu_if::OverlayBlock)));
    EXPECT_EQ(blockSize(p.id(), "ReduceBlock"), GLint(sizeof(gpu_if::ReduceBlock)));
    EXPECT_EQ(blockSize(p.id(), "ScreenBlock"), GLint(sizeof(gpu_if::ScreenBlock)));
}

TEST_F(ShaderInterfaceGLTest, CompileErrorNamesTheIncludedFileAndLine) {
    ShaderSources sources = embeddedShaders();
    sources["broken.frag"] = "#version 450 core\n#include \"interface.h\"\n#include \"broken.glsl\"\n"
                             "out vec4 o;\nvoid main() { o = vec4(f()); }\n";
    sources["broken.glsl"] = "// line 1\nfloat f() {\n    return undeclaredThing;\n}\n";
    try {
        linkShaderFiles("fullscreen.vert", "broken.frag", "broken", sources);
        FAIL() << "a shader using an undeclared name compiled";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        // One line names both the file and line of the mistake and the name (wording is the driver's).
        const std::size_t at = message.find("broken.glsl:3(");
        ASSERT_NE(at, std::string::npos) << message;
        EXPECT_LT(message.find("undeclaredThing", at), message.find('\n', at)) << message;
        EXPECT_EQ(message.find("broken.frag:3"), std::string::npos) << message;
    }
    expectDebugMessages(2);  // the undeclared name and the return type it spoils, through KHR_debug too  // the driver reports the compile error through KHR_debug too
}

TEST_F(ShaderInterfaceGLTest, ErrorAfterAnIncludeNamesTheMainFileAndItsOwnLine) {
    ShaderSources sources = embeddedShaders();
    sources["after.frag"] = "#version 450 core\n#include \"interface.h\"\nout vec4 o;\n"
                            "void main() { o = vec4(1.0) }\n";  // line 4: missing semicolon
    try {
        linkShaderFiles("fullscreen.vert", "after.frag", "after", sources);
        FAIL() << "a shader with a syntax error compiled";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("after.frag:4("), std::string::npos) << e.what();
    }
    expectDebugMessages(1);
}
