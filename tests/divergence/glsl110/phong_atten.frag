// Phong per pixel from a point light with constant, linear and quadratic attenuation (book §2.3.2, §5.6.2), GL 2.0 style on the fixed-function state: the original.
varying vec3 eyeNormal;
varying vec3 eyePosition;

void main()
{
    vec3 N = normalize(eyeNormal);
    vec3 aux = gl_LightSource[0].position.xyz - eyePosition;
    float dist = length(aux);
    vec3 L = aux / dist;
    vec3 E = normalize(-eyePosition);
    vec3 R = reflect(-L, N);
    float NdotL = max(dot(N, L), 0.0);
    float att = 1.0 / (gl_LightSource[0].constantAttenuation
                       + gl_LightSource[0].linearAttenuation * dist
                       + gl_LightSource[0].quadraticAttenuation * dist * dist);
    float spec = pow(max(dot(R, E), 0.0), gl_FrontMaterial.shininess);
    vec4 colour = gl_FrontMaterial.ambient * gl_LightModel.ambient;
    colour += att * (gl_FrontMaterial.diffuse * gl_LightSource[0].diffuse * NdotL
                     + gl_FrontMaterial.specular * gl_LightSource[0].specular * spec);
    gl_FragColor = vec4(colour.rgb, 1.0);
}
