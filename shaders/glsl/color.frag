// Pass-through fragment shader for per-vertex lighting (book §7.1.2): the colour was computed per vertex.
#version 450

layout(location = 0) in vec3 vertexColor;
layout(location = 0) out vec4 fragColor;

void main()
{
    fragColor = vec4(vertexColor, 1.0);
}
