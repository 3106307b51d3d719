// glTF 2.0 metallic-roughness, a Cook-Torrance microfacet BRDF (book §5.8.3), vertex stage in the glTF viewers' style: attributes switched on by HAS_NORMALS / HAS_TANGENTS / HAS_UV defines.
#version 330 core

layout(location = 0) in vec3 a_Position;
#ifdef HAS_NORMALS
layout(location = 1) in vec3 a_Normal;
#endif
#ifdef HAS_TANGENTS
layout(location = 2) in vec4 a_Tangent;
#endif
#ifdef HAS_UV
layout(location = 3) in vec2 a_UV;
#endif

uniform mat4 u_ModelMatrix;
uniform mat4 u_ViewProjectionMatrix;
uniform mat4 u_NormalMatrix;

out vec3 v_Position;
#ifdef HAS_NORMALS
#ifdef HAS_TANGENTS
out mat3 v_TBN;
#else
out vec3 v_Normal;
#endif
#endif
out vec2 v_UV;

void main()
{
    vec4 pos = u_ModelMatrix * vec4(a_Position, 1.0);
    v_Position = pos.xyz / pos.w;

#ifdef HAS_NORMALS
#ifdef HAS_TANGENTS
    vec3 normalW = normalize(vec3(u_NormalMatrix * vec4(a_Normal, 0.0)));
    vec3 tangentW = normalize(vec3(u_ModelMatrix * vec4(a_Tangent.xyz, 0.0)));
    vec3 bitangentW = cross(normalW, tangentW) * a_Tangent.w;
    v_TBN = mat3(tangentW, bitangentW, normalW);
#else
    v_Normal = normalize(vec3(u_NormalMatrix * vec4(a_Normal, 0.0)));
#endif
#endif

#ifdef HAS_UV
    v_UV = a_UV;
#else
    v_UV = vec2(0.0);
#endif

    gl_Position = u_ViewProjectionMatrix * pos;
}
