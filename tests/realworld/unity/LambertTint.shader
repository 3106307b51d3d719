// Lambert diffuse per pixel (book §5.5, §7.1.2) as a Unity built-in-pipeline ShaderLab shader: Properties, one SubShader, one pass, a CGPROGRAM block with #pragma entries and UnityCG.cginc.
Shader "Shaderbed/LambertTint"
{
    Properties
    {
        _Color ("Tint", Color) = (0.8, 0.6, 0.4, 1)
    }
    SubShader
    {
        Tags { "RenderType" = "Opaque" "LightMode" = "ForwardBase" }
        LOD 100

        Pass
        {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"

            fixed4 _Color;
            float4 _LightColor0;

            struct appdata
            {
                float4 vertex : POSITION;
                float3 normal : NORMAL;
            };

            struct v2f
            {
                float4 pos : SV_POSITION;
                float3 worldNormal : TEXCOORD0;
            };

            v2f vert (appdata v)
            {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.worldNormal = UnityObjectToWorldNormal(v.normal);
                return o;
            }

            fixed4 frag (v2f i) : SV_Target
            {
                float3 n = normalize(i.worldNormal);
                float3 l = normalize(_WorldSpaceLightPos0.xyz);
                float ndotl = max(0, dot(n, l));
                return fixed4(_Color.rgb * _LightColor0.rgb * ndotl, 1);
            }
            ENDCG
        }
    }
    FallBack "Diffuse"
}
