// Test shader for init's bindings (tests/author): per-pixel Blinn-Phong whose specular colour packs the exponent in w, as the comment says.
float4x4 WorldViewProj;
float3 LightDir;          // toward the light
float3 EyePos;
float4 DiffuseColor;
float4 SpecularColor;     // rgb = specular colour, w = specular power

struct VertexOut {
  float4 position : POSITION;
  float3 normal : TEXCOORD0;
  float3 world : TEXCOORD1;
};

VertexOut GlossVS(float4 position : POSITION, float3 normal : NORMAL) {
  VertexOut o;
  o.position = mul(WorldViewProj, position);
  o.normal = normal;
  o.world = position.xyz;
  return o;
}

float4 GlossPS(VertexOut i) : COLOR {
  const float3 n = normalize(i.normal);
  const float3 l = normalize(LightDir);
  const float3 h = normalize(l + normalize(EyePos - i.world));
  const float diffuse = saturate(dot(n, l));
  const float specular = diffuse > 0 ? pow(saturate(dot(n, h)), SpecularColor.w) : 0;
  return float4(DiffuseColor.rgb * diffuse + SpecularColor.rgb * specular, 1);
}
