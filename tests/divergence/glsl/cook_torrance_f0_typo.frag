// Cook-Torrance: Beckmann distribution, V-cavity masking-shadowing and Schlick's Fresnel over a Lambert base (book §5.8.3), ported to GLSL 4.50; planted bug (f0_typo): a constant typo: F0 = 0.4 instead of 0.04.
#version 450
layout(location = 0) in vec3 n_obj;
layout(location = 1) in vec3 to_viewer;
layout(location = 0) out vec4 out_colour;

layout(binding = 1) uniform Params {
    vec3 sun;               // object space, unit, toward the light
    float m;
    vec3 albedo;
    float k_spec;
};

const float F0 = 0.4;

void main()
{
    vec3 n = normalize(n_obj);
    vec3 v = normalize(to_viewer);
    vec3 h = normalize(v + sun);
    float nv = clamp(dot(n, v), 0.0, 1.0);
    float nl = clamp(dot(n, sun), 0.0, 1.0);
    float vh = clamp(dot(v, h), 0.0, 1.0);
    float nh = max(dot(n, h), 1e-4);
    float nh2 = nh * nh;
    float mm = m * m;
    float distribution = exp((nh2 - 1.0) / (mm * nh2)) / (mm * nh2 * nh2);
    float masking = min(1.0, 2.0 * nh * min(nv, nl) / vh);
    float fresnel = F0 + (1.0 - F0) * pow(1.0 - vh, 5.0);
    float brdf = distribution * masking * fresnel / max(4.0 * nl * nv, 1e-4);
    out_colour = vec4(nl * albedo + nl * (k_spec * brdf), 1.0);
}
