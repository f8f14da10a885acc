// Shades a tiled surface: the colour-mapped pattern, its relief through a
// tangent-space normal map (Turk 1991's bump mapping, baked by
// core/surface/textured_surface.cpp; the glTF convention, so an exported
// model looks the same elsewhere), one directional light.

uniform sampler2D uBaseColour;
uniform sampler2D uNormalMap;
uniform vec3 uEye;   // camera position, world space
uniform vec3 uLight; // towards the light, world space, unit

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec4 vTangent;

layout(location = 0) out vec4 outColour;

void main() {
    vec3 n = normalize(vNormal);
    // Re-orthogonalised after interpolation, as glTF viewers do.
    vec3 t = normalize(vTangent.xyz - n * dot(n, vTangent.xyz));
    vec3 b = cross(n, t) * vTangent.w;
    vec3 m = texture(uNormalMap, vUv).xyz * 2.0 - 1.0;
    vec3 normal = normalize(t * m.x + b * m.y + n * m.z);
    // The back of an open surface is lit as its front.
    if (!gl_FrontFacing)
        normal = -normal;
    vec3 base = texture(uBaseColour, vUv).rgb;
    vec3 view = normalize(uEye - vPosition);
    float diffuse = max(dot(normal, uLight), 0.0);
    float specular = pow(max(dot(normal, normalize(uLight + view)), 0.0), 40.0);
    outColour = vec4(base * (0.3 + 0.7 * diffuse) + 0.18 * specular, 1.0);
}
