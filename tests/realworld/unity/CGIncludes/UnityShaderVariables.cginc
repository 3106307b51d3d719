// shaderbed's own minimal stand-in for an engine header (not Unity's file): the per-object and per-camera uniforms the stand-in UnityCG.cginc uses; a case binds them by these names.
#ifndef SHADERBED_UNITY_SHADER_VARIABLES_STAND_IN
#define SHADERBED_UNITY_SHADER_VARIABLES_STAND_IN

float4x4 unity_ObjectToWorld;
float4x4 unity_WorldToObject;
float4x4 UNITY_MATRIX_VP;
float4 _WorldSpaceLightPos0;   // a directional light: the direction toward it, w = 0

#endif
