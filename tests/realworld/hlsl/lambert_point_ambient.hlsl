// Lambert diffuse per pixel with a point light and an ambient term (book §2.1, §2.5), as a D3D11 tutorial writes it: cbuffers with a padding member, separate row-vector world/view/projection matrices, mul(v, M).
cbuffer MatrixBuffer
{
    matrix worldMatrix;
    matrix viewMatrix;
    matrix projectionMatrix;
};

cbuffer LightBuffer
{
    float4 ambientColor;
    float4 diffuseColor;
    float3 lightPosition;   // world space
    float padding;
};

struct VertexInputType
{
    float4 position : POSITION;
    float3 normal : NORMAL;
};

struct PixelInputType
{
    float4 position : SV_POSITION;
    float3 normal : NORMAL;
    float3 worldPosition : TEXCOORD1;
};

PixelInputType LightVertexShader(VertexInputType input)
{
    PixelInputType output;
    input.position.w = 1.0f;
    float4 worldPosition = mul(input.position, worldMatrix);
    output.position = mul(worldPosition, viewMatrix);
    output.position = mul(output.position, projectionMatrix);
    output.normal = mul(input.normal, (float3x3)worldMatrix);
    output.worldPosition = worldPosition.xyz;
    return output;
}

float4 LightPixelShader(PixelInputType input) : SV_TARGET
{
    float3 lightDir = normalize(lightPosition - input.worldPosition);
    float3 normal = normalize(input.normal);
    float4 color = ambientColor + diffuseColor * saturate(dot(normal, lightDir));
    return float4(color.rgb, 1.0f);
}
