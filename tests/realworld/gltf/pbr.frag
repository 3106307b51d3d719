// glTF 2.0 metallic-roughness, a Cook-Torrance microfacet BRDF (book §5.8.3) with GGX distribution, Smith visibility and Schlick Fresnel, fragment stage in the glTF viewers' style with HAS_NORMALS / HAS_TANGENTS switches.
#version 330 core

const float M_PI = 3.141592653589793;

in vec3 v_Position;
#ifdef HAS_NORMALS
#ifdef HAS_TANGENTS
in mat3 v_TBN;
#else
in vec3 v_Normal;
#endif
#endif
in vec2 v_UV;

uniform vec3 u_Camera;
uniform vec3 u_LightDirection;   // world space, toward the light
uniform vec3 u_LightColor;
uniform vec4 u_BaseColorFactor;
uniform float u_MetallicFactor;
uniform float u_RoughnessFactor;

out vec4 FragColor;

// The shading normal: the vertex frame's when the mesh has one, else the face's.
vec3 getNormal()
{
#ifdef HAS_NORMALS
#ifdef HAS_TANGENTS
    // No normal texture here: the tangent-space normal is +Z.
    return normalize(v_TBN * vec3(0.0, 0.0, 1.0));
#else
    return normalize(v_Normal);
#endif
#else
    vec3 pos_dx = dFdx(v_Position);
    vec3 pos_dy = dFdy(v_Position);
    return normalize(cross(pos_dx, pos_dy));
#endif
}

vec3 fresnelSchlick(vec3 f0, float VdotH)
{
    return f0 + (vec3(1.0) - f0) * pow(clamp(1.0 - VdotH, 0.0, 1.0), 5.0);
}

float visibilitySmithGGX(float NdotL, float NdotV, float alphaRoughness)
{
    float a2 = alphaRoughness * alphaRoughness;
    float ggxV = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
    float ggxL = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
    float ggx = ggxV + ggxL;
    return ggx > 0.0 ? 0.5 / ggx : 0.0;
}

float distributionGGX(float NdotH, float alphaRoughness)
{
    float a2 = alphaRoughness * alphaRoughness;
    float f = (NdotH * NdotH) * (a2 - 1.0) + 1.0;
    return a2 / (M_PI * f * f);
}

void main()
{
    float metallic = clamp(u_MetallicFactor, 0.0, 1.0);
    float perceptualRoughness = clamp(u_RoughnessFactor, 0.04, 1.0);
    float alphaRoughness = perceptualRoughness * perceptualRoughness;
    vec4 baseColor = u_BaseColorFactor;

    vec3 f0 = mix(vec3(0.04), baseColor.rgb, metallic);
    vec3 diffuseColor = mix(baseColor.rgb * (1.0 - 0.04), vec3(0.0), metallic);

    vec3 n = getNormal();
    vec3 v = normalize(u_Camera - v_Position);
    vec3 l = normalize(u_LightDirection);
    vec3 h = normalize(l + v);

    float NdotL = clamp(dot(n, l), 0.0, 1.0);
    float NdotV = clamp(abs(dot(n, v)), 0.001, 1.0);
    float NdotH = clamp(dot(n, h), 0.0, 1.0);
    float VdotH = clamp(dot(v, h), 0.0, 1.0);

    vec3 F = fresnelSchlick(f0, VdotH);
    float Vis = visibilitySmithGGX(NdotL, NdotV, alphaRoughness);
    float D = distributionGGX(NdotH, alphaRoughness);

    vec3 diffuse = (vec3(1.0) - F) * diffuseColor / M_PI;
    vec3 specular = F * Vis * D;
    vec3 color = NdotL * u_LightColor * (diffuse + specular);

    FragColor = vec4(color, baseColor.a);
}
