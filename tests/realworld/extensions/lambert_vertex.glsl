// Lambert diffuse per pixel (book §5.5, §7.1.2), vertex stage in a .glsl file (the stage is read from what it writes), with a uniform left declared and never read.
#version 330 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;

uniform mat4 uModelViewProjection;
uniform float uTime;   // was for a wobble; unused now

out vec3 vNormal;

void main()
{
    vNormal = inNormal;
    gl_Position = uModelViewProjection * vec4(inPosition, 1.0);
}
