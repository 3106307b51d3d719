// Lambert or half-Lambert diffuse per pixel (book §5.5, §7.1.2), fragment stage in a .fsh file, switched by a bool uniform.
#version 330 core
in vec3 fragNormal;

uniform vec3 lightDirection;   // object space, toward the light
uniform vec3 diffuseColor;
uniform bool halfLambert;      // Valve's wrap: (0.5 N.L + 0.5)^2

out vec4 fragColor;

void main()
{
    float ndotl = dot(normalize(fragNormal), lightDirection);
    float diffuse = halfLambert ? pow(0.5 * ndotl + 0.5, 2.0) : max(ndotl, 0.0);
    fragColor = vec4(diffuseColor * diffuse, 1.0);
}
