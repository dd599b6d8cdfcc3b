// The GLSL of the peer workloads: one vertex shader for every pass, a depth-only fragment
// shader, and the shading one with an optional shadow-map lookup (1 tap or 3x3 PCF).
#pragma once

namespace shadowlab::peers {

// One vertex shader for every pass: a vec3 attribute reads as (x, y, z, 1), a vec4 one
// (the shadow volume's vertices, w = 0 at infinity) as it is. `invariant` makes the final
// pass of the volumes land on exactly the prepass's depths (depth test EQUAL).
inline constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec4 position;
uniform mat4 clipFromWorld;
out vec3 worldPosition;
invariant gl_Position;
void main() {
    worldPosition = position.xyz;
    gl_Position = clipFromWorld * position;
}
)";

inline constexpr const char* kDepthOnlyFragment = R"(#version 330 core
void main() {}
)";

// Shading of the camera pass: the triangle's geometric normal (from a buffer texture, by
// gl_PrimitiveID), turned towards the eye as the G-buffer's; Lambert from the point light
// with V from a shadow-map lookup (SHADOW_MAP) or 1 (the volumes' pass, which only draws
// where the stencil is 0). The lookup is shadowlab's (shadows/maps/shadow_lookup.h, pcf.h):
// the receiver's window depth in the light's view against the texel it falls in, or the
// (2r+1)^2 texels around it (grid PCF, equal weights); coordinates clamp to the border; an
// empty texel (depth 1) is lit; the slope-scaled bias is in the map (polygon offset).
inline constexpr const char* kShadeFragment = R"(
uniform samplerBuffer triangleNormals;
uniform vec3 eye;
uniform vec3 lightPosition;
in vec3 worldPosition;
out vec4 color;
#ifdef SHADOW_MAP
uniform sampler2D lightDepth;
uniform mat4 lightClipFromWorld;
uniform int mapSize;
uniform int pcfRadius;
float shadowMapVisibility(vec3 P) {
    vec4 c = lightClipFromWorld * vec4(P, 1.0);
    vec3 ndc = c.xyz / c.w;
    vec2 texel = (ndc.xy * 0.5 + 0.5) * float(mapSize);
    float depth = ndc.z * 0.5 + 0.5;
    ivec2 base = ivec2(floor(texel));
    float lit = 0.0;
    for (int dy = -pcfRadius; dy <= pcfRadius; ++dy) {
        for (int dx = -pcfRadius; dx <= pcfRadius; ++dx) {
            ivec2 q = clamp(base + ivec2(dx, dy), ivec2(0), ivec2(mapSize - 1));
            float stored = texelFetch(lightDepth, q, 0).r;
            lit += (stored >= 1.0 || depth <= stored) ? 1.0 : 0.0;
        }
    }
    float taps = float((2 * pcfRadius + 1) * (2 * pcfRadius + 1));
    return lit / taps;
}
#endif
void main() {
    vec3 P = worldPosition;
    vec3 N = texelFetch(triangleNormals, gl_PrimitiveID).xyz;
    if (dot(N, eye - P) < 0.0) N = -N;
    vec3 toLight = lightPosition - P;
    float cosine = dot(N, normalize(toLight));
    float V = 0.0;
    if (cosine > 0.0) {
#ifdef SHADOW_MAP
        V = shadowMapVisibility(P);
#else
        V = 1.0;
#endif
    }
    float radiance = 0.03 + 0.8 * V * max(cosine, 0.0);
    color = vec4(vec3(pow(radiance, 1.0 / 2.2)), 1.0);
}
)";

}  // namespace shadowlab::peers
