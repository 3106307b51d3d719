// Ambient term (book §2.5, Appendix C GLSL ambient): one constant colour for every vertex.
#version 450

layout(location = 0) in vec3 position;

layout(std140, binding = 0) uniform Ambient {
    mat4 modelViewProjection;
    vec3 ambientColor;
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vertexColor = ambientColor;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
