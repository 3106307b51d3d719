// Test shader for init's bindings (tests/author): the HLSL port of brdf.vert/brdf.frag, without the debug factor.
cbuffer PerDraw {
  float4x4 g_WorldViewProjection;
  float3 g_LightDirection;
  float3 g_CameraPosition;
  float3 g_DiffuseColor;
  float3 g_SpecularColor;
  float g_SpecularPower;
};

struct VSOutput {
  float4 position : SV_Position;
  float3 normal : NORMAL;
  float3 object : TEXCOORD0;
};

VSOutput BrdfVS(float3 position : POSITION, float3 normal : NORMAL) {
  VSOutput o;
  o.position = mul(g_WorldViewProjection, float4(position, 1));
  o.normal = normal;
  o.object = position;
  return o;
}

float4 BrdfPS(VSOutput i) : SV_Target {
  const float3 n = normalize(i.normal);
  const float3 l = normalize(g_LightDirection);
  const float3 h = normalize(l + normalize(g_CameraPosition - i.object));
  const float ndotl = max(dot(n, l), 0);
  const float3 spec = ndotl > 0 ? g_SpecularColor * pow(max(dot(n, h), 0), g_SpecularPower) : 0;
  return float4(g_DiffuseColor * ndotl + spec, 1);
}
