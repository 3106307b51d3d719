// Phong per pixel (book §5.6.2), the "~/port" GLSL 3.30 port of phong.hlsl in the README's examples: fragment stage.
#version 330 core
in vec3 vNormal;
in vec3 vView;

uniform vec3 LightDir;
uniform vec3 DiffuseColor;
uniform vec4 SpecularColor;

out vec4 fragColor;

void main()
{
    vec3 n = normalize(vNormal);
    vec3 v = normalize(vView);
    vec3 r = reflect(-LightDir, n);
    float diffuse = clamp(dot(n, LightDir), 0.0, 1.0);
    float specular = pow(clamp(dot(r, v), 0.0, 1.0), SpecularColor.w);
    fragColor = vec4(DiffuseColor * diffuse + SpecularColor.rgb * specular, 1.0);
}
