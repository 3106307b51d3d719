// The same highlight as lobe_naive.frag with tan^2 from |N x H|^2, which does not cancel.
// For tests/hard (hard --case).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform Lobe {
    vec3 lightDirection;
    vec3 eyePosition;
    vec3 diffuseColor;
    float slopeM;
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 h = normalize(lightDirection + normalize(eyePosition - objectPosition));
    float nDotL = max(dot(n, lightDirection), 0.0);
    float nDotH = dot(n, h);
    vec3 across = cross(n, h);
    float tan2 = dot(across, across) / (nDotH * nDotH);
    float lobe = nDotH > 0.0 ? exp(-tan2 / (slopeM * slopeM)) : 0.0;
    fragColor = vec4(diffuseColor * (0.5 * nDotL + lobe), 1.0);
}
