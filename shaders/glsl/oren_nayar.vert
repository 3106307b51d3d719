// Oren-Nayar, per vertex (book §5.7.1, §7.3): D max(0,N.L) (A + B max(0,cos C) sin(alpha) tan(beta)), A and B from sigma^2.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform OrenNayarVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;     // object space, unit, toward the light
    vec3 eyePosition;        // object space
    vec3 diffuseColor;
    float roughnessSquared;  // sigma^2: A and B depend on it alone
};

layout(location = 0) out vec3 vertexColor;

// Cosine of the azimuth between V and L, both projected onto the tangent plane. A projection
// vanishes when the vector is along N; beta is 0 there, so the B term is 0 anyway (errata E8).
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
    // Renormalised: a normal a little longer than 1 puts the dots past +-1, where the clamp
    // below turns sin(alpha) near alpha = pi into 0 (20 % error for 1e-4 of length; docs/hard-cases.md).
    vec3 n = normalize(normal);
    vec3 toEye = normalize(eyePosition - position);
    float nDotV = dot(n, toEye);
    float nDotL = dot(n, lightDirection);

    // max(0, N.L) = 0 zeroes the colour; testing it first also keeps tan(beta) finite below.
    vec3 color = vec3(0.0);
    if (nDotL > 0.0) {
        // sin(alpha) tan(beta) straight from the dots: acos falls, so alpha = acos(min dot) and
        // beta = acos(max dot), and sin(acos c) = sqrt(1 - c^2), tan(acos c) = sqrt(1 - c^2)/c.
        // The same function as the angles without the driver's acos (Mesa's is off by up to
        // 1.6e-4 rad) or tan's loss of precision near 90 degrees. Clamped as for acos (errata E9).
        float cosAlpha = clamp(min(nDotV, nDotL), -1.0, 1.0);
        float cosBeta = clamp(max(nDotV, nDotL), -1.0, 1.0);   // >= N.L > 0
        float sinAlpha = sqrt((1.0 - cosAlpha) * (1.0 + cosAlpha));
        float tanBeta = sqrt((1.0 - cosBeta) * (1.0 + cosBeta)) / cosBeta;

        float a = 1.0 - 0.5 * roughnessSquared / (roughnessSquared + 0.33);
        float b = 0.45 * roughnessSquared / (roughnessSquared + 0.09);
        float cosC = cosAzimuth(n, toEye, nDotV, lightDirection, nDotL);
        color = diffuseColor * nDotL * (a + b * cosC * sinAlpha * tanBeta);
    }
    vertexColor = color;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
