// Oren-Nayar rough diffuse times an albedo texture (book §5.7.1), ported to GL 2.0-era GLSL: the vertex shader every port shares.
uniform vec3 viewerPos;

varying vec3 objNormal;
varying vec3 objToViewer;

void main()
{
    objNormal = gl_Normal;
    objToViewer = viewerPos - gl_Vertex.xyz;
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
