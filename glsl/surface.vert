// A tiled surface's grid vertices (gl/surface_view.cpp): world-space
// attributes passed on for per-pixel shading.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aTangent; // xyz along +u, w: bitangent = w * cross(normal, tangent)

uniform mat4 uViewProjection;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;
out vec4 vTangent;

void main() {
    vPosition = aPosition;
    vNormal = aNormal;
    vUv = aUv;
    vTangent = aTangent;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
