// Pass-through pixel shader for per-vertex lighting (book §7.1.2): the colour was computed in the vertex shader.
struct PS_INPUT
{
    float3 Diffuse : COLOR0;
};

float4 main(const PS_INPUT In) : COLOR0
{
    return float4(In.Diffuse, 1.0f);
}
