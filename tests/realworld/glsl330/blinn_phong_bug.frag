// Blinn-Phong per pixel, GLSL 3.30 core with loose uniforms (book §5.6.3; point light of Ch. 2).
// Planted bug: the light vector is used without normalize().
#version 330 core
out vec4 FragColor;

in vec3 FragPos;
in vec3 Normal;

uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 ambientColor;
uniform vec3 objectColor;
uniform vec3 specularColor;
uniform float shininess;

void main()
{
    vec3 norm = normalize(Normal);
    vec3 lightDir = lightPos - FragPos;
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 halfwayDir = normalize(lightDir + viewDir);

    float diff = max(dot(norm, lightDir), 0.0);
    float spec = pow(max(dot(norm, halfwayDir), 0.0), shininess);

    vec3 result = ambientColor + (diff * objectColor + spec * specularColor) * lightColor;
    FragColor = vec4(result, 1.0);
}
