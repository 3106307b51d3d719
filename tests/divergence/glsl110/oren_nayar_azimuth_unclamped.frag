// Oren-Nayar rough diffuse times an albedo texture (book §5.7.1), ported to GL 2.0-era GLSL; planted bug (azimuth_unclamped): max(0, cos(phi)) missing: the azimuth term goes negative.
uniform vec3 sunDir;
uniform float roughnessSq;
uniform sampler2D diffuseTex;

varying vec3 objNormal;
varying vec3 objToViewer;

void main()
{
    vec3 n = normalize(objNormal);
    vec3 v = normalize(objToViewer);
    float cosI = dot(n, sunDir);
    float cosR = dot(n, v);
    float angI = acos(clamp(cosI, -1.0, 1.0));
    float angR = acos(clamp(cosR, -1.0, 1.0));
    float termA = 1.0 - 0.5 * roughnessSq / (roughnessSq + 0.33);
    float termB = 0.45 * roughnessSq / (roughnessSq + 0.09);
    vec3 vPlane = normalize(v - cosR * n);
    vec3 lPlane = normalize(sunDir - cosI * n);
    float azimuth = dot(vPlane, lPlane);
    float angular = sin(max(angI, angR)) * tan(min(angI, angR));
    vec3 texel = texture2D(diffuseTex, gl_TexCoord[0].st).rgb;
    gl_FragColor = vec4(texel * max(cosI, 0.0) * (termA + termB * azimuth * angular), 1.0);
}
