// Phong per pixel (book §5.6.2, §7.2.1), the "~/port" original of the README's examples: both stages in one file, the author's uniform names.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
float3   EyePosition;       // object space
float3   DiffuseColor;
float4   SpecularColor;     // rgb = colour, w = specular power

struct VertexIn
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float3 View     : TEXCOORD1;
};

VertexOut PhongVS(VertexIn input)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, input.Position);
    output.Normal = input.Normal;
    output.View = EyePosition - input.Position.xyz;
    return output;
}

float4 PhongPS(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    float3 v = normalize(input.View);
    float3 r = reflect(-LightDir, n);
    float diffuse = saturate(dot(n, LightDir));
    float specular = pow(saturate(dot(r, v)), SpecularColor.w);
    return float4(DiffuseColor * diffuse + SpecularColor.rgb * specular, 1.0);
}
