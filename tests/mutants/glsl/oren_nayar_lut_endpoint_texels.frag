// Oren-Nayar, per pixel with the angle LUT (book §5.7.1, §7.3 OrenNayar_PS), MUTANT: the lookup treats the first and last texel centres as N.V, N.L = -1 and +1 (an endpoint-inclusive table), while the LUT holds texel i at 2 (i + 0.5) / n - 1: every lookup is off by up to half a texel, most at the edges of the table.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform OrenNayarPixel {
    vec3 lightDirection;     // object space, unit, toward the light
    vec3 eyePosition;        // object space
    vec3 diffuseColor;
    float roughnessSquared;  // sigma^2
};

// R32F, texel (i, j) holds sin(alpha) tan(beta) at N.V = 2u - 1, N.L = 2v - 1; linear, clamp to edge.
layout(binding = 2) uniform sampler2D angleLut;

layout(location = 0) out vec4 fragColor;

float cosAzimuth(vec3 n, vec3 toEye, float nDotV, vec3 toLight, float nDotL)
{
    vec3 eyeInPlane = toEye - n * nDotV;
    vec3 lightInPlane = toLight - n * nDotL;
    if (dot(eyeInPlane, eyeInPlane) < 1e-12 || dot(lightInPlane, lightInPlane) < 1e-12)
        return 0.0;
    return max(dot(normalize(eyeInPlane), normalize(lightInPlane)), 0.0);
}

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    float nDotV = dot(n, toEye);
    float nDotL = dot(n, lightDirection);

    // Planted bug: (t (n - 1) + 0.5) / n puts t = 0 and t = 1 on the edge texels' centres.
    vec2 size = vec2(textureSize(angleLut, 0));
    vec2 t = 0.5 * vec2(nDotV, nDotL) + 0.5;
    float angleTerm = texture(angleLut, (t * (size - 1.0) + 0.5) / size).r;

    float a = 1.0 - 0.5 * roughnessSquared / (roughnessSquared + 0.33);
    float b = 0.45 * roughnessSquared / (roughnessSquared + 0.09);
    float cosC = cosAzimuth(n, toEye, nDotV, lightDirection, nDotL);

    fragColor = vec4(diffuseColor * max(nDotL, 0.0) * (a + b * cosC * angleTerm), 1.0);
}
