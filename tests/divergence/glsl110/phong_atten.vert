// Phong per pixel from a point light with constant, linear and quadratic attenuation (book §2.3.2, §5.6.2), GL 2.0 style on the fixed-function state: the original's vertex shader.
varying vec3 eyeNormal;
varying vec3 eyePosition;

void main()
{
    eyePosition = vec3(gl_ModelViewMatrix * gl_Vertex);
    eyeNormal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
