// Blinn-Phong per pixel, GL-tutorial style with fixed-function built-ins (book §5.6.3; point light of Ch. 2).
varying vec3 ecPosition;
varying vec3 ecNormal;

void main()
{
    vec3 N = normalize(ecNormal);
    vec3 L = normalize(gl_LightSource[0].position.xyz - ecPosition);
    vec3 V = normalize(-ecPosition);          // the eye sits at the origin of eye space
    vec3 H = normalize(L + V);

    float diffuseTerm = max(dot(N, L), 0.0);
    float specularTerm = pow(max(dot(N, H), 0.0), gl_FrontMaterial.shininess);

    vec4 color = gl_FrontLightModelProduct.sceneColor;
    color += gl_FrontLightProduct[0].diffuse * diffuseTerm;
    color += gl_FrontLightProduct[0].specular * specularTerm;
    gl_FragColor = vec4(color.rgb, 1.0);
}
