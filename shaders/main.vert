#version 450 core
layout(location = 0) in vec3 aPosition;  // ws
layout(location = 1) in vec3 aNormal;    // ws
layout(location = 2) in vec2 aUv;
uniform mat4 uView;
uniform mat4 uViewProj;
out vec3 vWsPosition;
out vec3 vWsNormal;
out vec2 vUv;
out float vVsDepth;  // positive distance along the view axis, compared with the split depths
void main() {
    vWsPosition = aPosition;
    vWsNormal = aNormal;
    vUv = aUv;
    vVsDepth = -(uView * vec4(aPosition, 1.0)).z;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
