// Lambert diffuse, per pixel (book §5.5), MUTANT (window-origin convention): the normal is rebuilt from screen-space derivatives, N = normalize(cross(ddx(P), ddy(P))), an order that is right only where window y grows downwards (D3D, Vulkan). On GL window y grows upwards, ddy changes sign and N points into the surface. Only a flat-faced shape (the cube) can match the reference at all.
float3 LightVector  : register(c4);
float3 DiffuseColor : register(c7);

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    // planted bug: the facet normal's sign depends on the API's window y direction
    float3 N = normalize(cross(ddx(In.InterPos), ddy(In.InterPos)));
    return float4(DiffuseColor * max(0.0f, dot(LightVector, N)), 1.0f);
}
