// Blinn-Phong per pixel, GL-tutorial style with fixed-function built-ins (book §5.6.3; point light of Ch. 2).
// Planted bug: the normal goes through gl_ModelViewMatrix instead of gl_NormalMatrix.
varying vec3 ecPosition;
varying vec3 ecNormal;

void main()
{
    ecPosition = vec3(gl_ModelViewMatrix * gl_Vertex);
    ecNormal = vec3(gl_ModelViewMatrix * vec4(gl_Normal, 1.0));
    gl_Position = ftransform();
}
