#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 2) in vec2 aUv;
uniform mat4 uViewProj;  // world -> light clip of the cascade being rendered
out vec2 vUv;
void main() {
    vUv = aUv;
    gl_Position = uViewProj * vec4(aPosition, 1.0);
}
