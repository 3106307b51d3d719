// Ward anisotropic, per vertex (book §5.8.1, §7.5.2): (D + S/(4 pi sx sy)/sqrt(N.L N.V) exp(-2((H.X/sx)^2 + (H.Y/sy)^2)/(1 + N.H))) max(0,N.L).
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 tangent;

layout(std140, binding = 0) uniform WardAnisoVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    vec2 roughness;        // (sigma x, sigma y): along the tangent, along N x tangent
};

layout(location = 0) out vec3 vertexColor;

const float pi = 3.14159265358979;

void main()
{
    vec3 toEye = normalize(eyePosition - position);
    vec3 halfVector = normalize(lightDirection + toEye);
    float nDotL = dot(normal, lightDirection);
    float nDotV = dot(normal, toEye);

    // The BRDF lives on the upper hemisphere: 1/sqrt(N.L N.V) is NaN or infinite elsewhere (errata E4).
    // Frame from the mesh tangent, not the book's cross(N, z), which vanishes where N is along z
    // (errata E3). A tangent along N leaves X undefined: no specular there, as the reference.
    vec3 tangentInPlane = tangent - normal * dot(normal, tangent);
    vec3 specular = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0 && dot(tangentInPlane, tangentInPlane) >= 1e-12) {
        vec3 x = normalize(tangentInPlane);
        vec3 y = cross(normal, x);
        vec2 h = vec2(dot(halfVector, x), dot(halfVector, y)) / roughness;
        float exponent = -2.0 * dot(h, h) / (1.0 + dot(normal, halfVector));
        // Ward's normalisation 1/(4 pi sx sy) (errata E2).
        specular = specularColor * (exp(exponent) / (4.0 * pi * roughness.x * roughness.y) / sqrt(nDotL * nDotV));
    }
    vertexColor = (diffuseColor + specular) * max(nDotL, 0.0);
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
