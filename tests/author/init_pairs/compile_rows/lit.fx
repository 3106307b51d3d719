// Test shader for init's check (tests/author): a DX9 effect whose technique hands its matrices to the vertex shader through `compile` arguments, used as row vectors (mul(v, M)).
float4x4 g_WorldViewProj;
float4x4 g_World;
float3 g_LightDirection;   // toward the light
float4 g_Diffuse;

struct VS_OUT {
  float4 position : POSITION;
  float3 normal : TEXCOORD0;
};

VS_OUT SceneVS(float4 position : POSITION, float3 normal : NORMAL, uniform float4x4 wvp, uniform float4x4 world) {
  VS_OUT o;
  o.position = mul(position, wvp);
  o.normal = mul(normal, (float3x3)world);
  return o;
}

float4 ScenePS(VS_OUT i) : COLOR {
  const float lambert = saturate(dot(normalize(i.normal), normalize(g_LightDirection)));
  return float4(g_Diffuse.rgb * lambert, g_Diffuse.a);
}

technique Lit {
  pass P0 {
    VertexShader = compile vs_2_0 SceneVS(g_WorldViewProj, g_World);
    PixelShader = compile ps_2_0 ScenePS();
  }
}
