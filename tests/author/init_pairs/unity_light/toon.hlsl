// Test shader for init's bindings (tests/author): a Unity-style forward-base Lambert in plain HLSL, lit by _WorldSpaceLightPos0 (w = 0: a direction).
float4x4 UNITY_MATRIX_MVP;
float4x4 unity_ObjectToWorld;
float4 _WorldSpaceLightPos0;
float4 _LightColor0;
float4 _Color;

struct appdata {
  float4 vertex : POSITION;
  float3 normal : NORMAL;
};

struct v2f {
  float4 pos : SV_POSITION;
  float3 worldNormal : TEXCOORD0;
};

v2f vert(appdata v) {
  v2f o;
  o.pos = mul(UNITY_MATRIX_MVP, v.vertex);
  o.worldNormal = mul((float3x3)unity_ObjectToWorld, v.normal);
  return o;
}

float4 frag(v2f i) : SV_Target {
  // Forward base: the main directional light, its direction straight from the uniform.
  const float3 lightDir = _WorldSpaceLightPos0.xyz;
  const float ndotl = saturate(dot(normalize(i.worldNormal), lightDir));
  return float4(_Color.rgb * _LightColor0.rgb * ndotl, _Color.a);
}
