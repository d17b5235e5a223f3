#version 110
#define SCALE(x, k) ((x) * (k))
#if defined(SCALE) && __VERSION__ >= 110 && !defined(GL_ES)
#define FACTOR 2.0
#else
#error unreachable
#endif
#line 100
#extension GL_ARB_texture_rectangle : enable
void main()
{
    gl_Position = ftransform();
    gl_FrontColor = vec4(SCALE(gl_Color.rgb, FACTOR), 1.0);
    gl_PointSize = 4.0;
    gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;
}
