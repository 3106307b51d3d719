// shaderbed's own minimal stand-in for an engine header (not Unity's file): the few built-in names the test shaders in tests/realworld/unity read, so a .shader written against it compiles unchanged.
#ifndef SHADERBED_UNITY_CG_STAND_IN
#define SHADERBED_UNITY_CG_STAND_IN

#include "UnityShaderVariables.cginc"

// Object space to clip space, through world space as the engine composes it.
inline float4 UnityObjectToClipPos(float4 objectPosition)
{
    return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, float4(objectPosition.xyz, 1.0)));
}

// A normal to world space: the inverse transpose, written as a row vector times the inverse.
inline float3 UnityObjectToWorldNormal(float3 objectNormal)
{
    return normalize(mul(objectNormal, (float3x3)unity_WorldToObject));
}

#endif
