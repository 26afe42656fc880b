#include "renderer/render/shadow_uniforms.h"

#include "renderer/csm/conventions.h"
#include "shaders/limits.h"

#include <glm/gtc/type_ptr.hpp>

namespace st {
namespace {
GLint loc(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

int filterCode(FilterKind k) {
    switch (k) {
    case FilterKind::Hard: return ST_FILTER_HARD;
    case FilterKind::PcfNxN: return ST_FILTER_PCF_NXN;
    default: return ST_FILTER_PCF2X2;
    }
}
}  // namespace

void setShadowUniforms(GLuint p, const Settings& s, const csm::CascadePlan& plan) {
    int n = s.cascades.count;
    glm::mat4 shadowMatrices[ST_MAX_CASCADES];
    float texel[ST_MAX_CASCADES], range[ST_MAX_CASCADES];
    for (int i = 0; i < n; ++i) {
        const csm::CascadeFit& f = plan.cascades[i];
        shadowMatrices[i] = csm::clipToTexture() * f.viewProj;
        texel[i] = f.texelWorldSize;
        range[i] = f.lsBox.extent().z;
    }
    glProgramUniform1i(p, loc(p, "uCascadeCount"), n);
    glProgramUniform1fv(p, loc(p, "uSplits"), n + 1, plan.splits.data());
    glProgramUniformMatrix4fv(p, loc(p, "uShadowMatrix"), n, GL_FALSE, glm::value_ptr(shadowMatrices[0]));
    glProgramUniform1fv(p, loc(p, "uTexelWorld"), n, texel);
    glProgramUniform1fv(p, loc(p, "uDepthRange"), n, range);
    glProgramUniform1i(p, loc(p, "uSelection"), s.cascades.selection == Selection::Map ? ST_SELECT_MAP : ST_SELECT_INTERVAL);
    glProgramUniform1f(p, loc(p, "uBlendBand"), s.cascades.blendBand);
    glProgramUniform1i(p, loc(p, "uFilter"), filterCode(s.filter.kind));
    glProgramUniform1i(p, loc(p, "uFilterSize"), s.filter.size);
    glProgramUniform1f(p, loc(p, "uMapSize"), float(s.cascades.mapSize));
    glProgramUniform1f(p, loc(p, "uBiasConstant"), s.bias.constant);
    glProgramUniform1f(p, loc(p, "uBiasSlope"), s.bias.slope);
    glProgramUniform1f(p, loc(p, "uNormalOffset"), s.bias.normalOffset);
    glProgramUniform1i(p, loc(p, "uReceiverPlane"), s.bias.receiverPlane);
}

}  // namespace st
