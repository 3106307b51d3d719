// Cook-Torrance with Beckmann, V-cavity masking and Schlick's Fresnel (book §5.8.3), ported to GLSL 4.50: the vertex stage every port shares.
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 n_obj;
layout(location = 1) out vec3 to_viewer;

layout(binding = 0) uniform Xform {
    mat4 clip_from_object;
    vec3 viewer;
};

void main()
{
    to_viewer = viewer - position.xyz;
    n_obj = normal;
    gl_Position = clip_from_object * position;
}
