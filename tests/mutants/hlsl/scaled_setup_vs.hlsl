// Setup vertex shader for per-pixel lighting (book §6.3.1, Basic_PS20_Setup), MUTANT: the drawn position is scaled by 1.02 (a stray world scale) while the lighting still uses the unscaled position and normal; the object is drawn 2% too large.
matrix Transform : register(c0);   // World * View * Projection

struct VS_INPUT
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

VS_OUTPUT main(const VS_INPUT InVertex)
{
    VS_OUTPUT OutVertex;
    OutVertex.Position = mul(Transform, float4(InVertex.Position.xyz * 1.02f, 1.0f));   // planted bug
    OutVertex.InterPos = InVertex.Position.xyz;
    OutVertex.Normal   = InVertex.Normal;
    return OutVertex;
}
