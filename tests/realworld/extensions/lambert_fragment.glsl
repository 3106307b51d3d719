// Lambert diffuse per pixel (book §5.5, §7.1.2), fragment stage in a .glsl file, with a shadow-map sampler left declared and never sampled.
#version 330 core
in vec3 vNormal;

uniform vec3 uLightDirection;   // object space, toward the light
uniform vec3 uDiffuse;
uniform sampler2D uShadowMap;

out vec4 outColor;

void main()
{
    vec3 n = normalize(vNormal);
    outColor = vec4(uDiffuse * max(dot(n, uLightDirection), 0.0), 1.0);
}
