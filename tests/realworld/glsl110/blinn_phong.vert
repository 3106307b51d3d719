// Blinn-Phong per pixel, GL-tutorial style with fixed-function built-ins (book §5.6.3; point light of Ch. 2).
varying vec3 ecPosition;
varying vec3 ecNormal;

void main()
{
    // Eye space: the fragment shader lights there, with the light GL keeps in eye space.
    ecPosition = vec3(gl_ModelViewMatrix * gl_Vertex);
    ecNormal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
