// Shades a tiled surface: the colour-mapped pattern, its relief through a
// tangent-space normal map (Turk 1991's bump mapping, baked by
// core/surface/textured_surface.cpp; the glTF convention, so an exported
// model looks the same elsewhere), one directional light.
//
// With uWet = 1 the surface also has a glTF metallic-roughness texture
// (roughness in G: TexturedMesh::metallicRoughness) and is shaded as water
// where it is smooth (Lo et al. 5.6's drops "shaded as water"): wet texels
// darken a little (wet paper and wet skin do), reflect a sky-and-ground
// environment by Schlick's Fresnel term and carry a sharp highlight; the bump
// there comes from the water's height. Dry texels (roughness 0.7 and above)
// shade exactly as with uWet = 0.

uniform sampler2D uBaseColour;
uniform sampler2D uNormalMap;
uniform sampler2D uMetallicRoughness;
uniform int uWet;
uniform vec3 uEye;   // camera position, world space
uniform vec3 uLight; // towards the light, world space, unit

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec4 vTangent;

layout(location = 0) out vec4 outColour;

// A studio-like environment in world space (y up): a bright horizon fading
// to a blue zenith above, a warm grey floor below, so a curved wet surface
// shows the sky's gradient and a horizon line as water does.
vec3 environment(vec3 r) {
    float up = r.y;
    vec3 sky = mix(vec3(0.92, 0.94, 0.97), vec3(0.38, 0.55, 0.82), sqrt(max(up, 0.0)));
    vec3 ground = mix(vec3(0.62, 0.58, 0.52), vec3(0.22, 0.2, 0.18), sqrt(max(-up, 0.0)));
    return up >= 0.0 ? sky : ground;
}

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
    float nh = max(dot(normal, normalize(uLight + view)), 0.0);
    if (uWet == 0) {
        outColour = vec4(base * (0.3 + 0.7 * diffuse) + 0.18 * pow(nh, 40.0), 1.0);
        return;
    }
    float roughness = texture(uMetallicRoughness, vUv).g;
    float wet = clamp((0.7 - roughness) / (0.7 - 0.08), 0.0, 1.0);
    vec3 lit = mix(base, base * 0.82, wet) * (0.3 + 0.7 * diffuse);
    float specular = mix(0.18 * pow(nh, 40.0), 1.1 * pow(nh, 300.0), wet);
    // Clamped: where the normal faces the eye, rounding can put the dot a hair
    // over 1, and pow of a negative base is undefined (NaN on llvmpipe).
    float fresnel = 0.02 + 0.98 * pow(clamp(1.0 - dot(normal, view), 0.0, 1.0), 5.0);
    vec3 reflection = environment(reflect(-view, normal));
    outColour = vec4(lit + wet * (mix(0.1, 1.0, fresnel) * reflection - 0.1 * lit) + specular, 1.0);
}
