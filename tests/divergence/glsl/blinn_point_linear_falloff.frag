// Blinn-Phong lit by a point light with inverse-square falloff, plus an ambient floor (book §2.1.2, §5.6.3), ported to GLSL 4.50; planted bug (linear_falloff): attenuation by the distance d instead of d squared.
#version 450
layout(location = 0) in vec3 surfNormal;
layout(location = 1) in vec3 lightVec;
layout(location = 2) in vec3 eyeVec;
layout(location = 0) out vec4 fragColor;

layout(binding = 1) uniform Surface {
    vec3 kd;
    float ka;
    vec3 ks;
    float gloss;
    float power;
};

void main()
{
    vec3 n = normalize(surfNormal);
    vec3 v = normalize(eyeVec);
    vec3 l = normalize(lightVec);
    float r2 = dot(lightVec, lightVec);
    vec3 h = normalize(l + v);
    float nDotL = clamp(dot(n, l), 0.0, 1.0);
    float nDotH = clamp(dot(n, h), 0.0, 1.0);
    float highlight = nDotL > 0.0 ? pow(nDotH, gloss) : 0.0;
    float atten = power / sqrt(r2);
    vec3 direct = atten * (kd * nDotL + ks * highlight);
    fragColor = vec4(direct + ka * kd, 1.0);
}
