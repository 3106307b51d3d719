// SH irradiance per pixel (Ramamoorthi-Hanrahan 2001; the per-pixel SH the book's Ch. 9 leaves to the SDK): E(n) = sum_i E_i y_i(n), 3 bands.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform ShIrradiance {
    vec4 irradiance[9];   // rgb: A_l L_i albedo/pi, the light convolved with the clamped cosine
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 s = vec3(n.x, -n.z, n.y);   // y_i of the unit normal in the SH frame s = (n.x, -n.z, n.y), i = l(l+1)+m, Condon-Shortley signs
    vec3 e = irradiance[0].rgb * 0.282094791773878
           - irradiance[1].rgb * (0.488602511902920 * s.y)
           + irradiance[2].rgb * (0.488602511902920 * s.z)
           - irradiance[3].rgb * (0.488602511902920 * s.x)
           + irradiance[4].rgb * (1.092548430592079 * s.x * s.y)
           - irradiance[5].rgb * (1.092548430592079 * s.y * s.z)
           + irradiance[6].rgb * (0.315391565252520 * (3.0 * s.z * s.z - 1.0))
           - irradiance[7].rgb * (1.092548430592079 * s.x * s.z)
           + irradiance[8].rgb * (0.546274215296040 * (s.x * s.x - s.y * s.y));
    fragColor = vec4(e, 1.0);
}
