// Test shader for init's bindings (tests/author): an SM5 textured Lambert that tiles its texture twice, sampled through a SamplerState.
cbuffer Transforms : register(b0) {
  float4x4 worldViewProjection;
  float3 lightDirection;
};

Texture2D tilesTexture : register(t0);
SamplerState tileSampler : register(s0);

struct VSIn {
  float3 position : POSITION;
  float3 normal : NORMAL;
  float2 uv : TEXCOORD0;
};

struct PSIn {
  float4 position : SV_Position;
  float3 normal : NORMAL;
  float2 uv : TEXCOORD0;
};

PSIn TiledVS(VSIn v) {
  PSIn o;
  o.position = mul(worldViewProjection, float4(v.position, 1));
  o.normal = v.normal;
  o.uv = v.uv * 2;
  return o;
}

float4 TiledPS(PSIn i) : SV_Target {
  const float lambert = saturate(dot(normalize(i.normal), normalize(lightDirection)));
  return float4(tilesTexture.Sample(tileSampler, i.uv).rgb * lambert, 1);
}
