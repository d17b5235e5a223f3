#version 120
uniform mat4 mvp;
uniform vec3 light[2];
attribute vec3 normal_in;
varying vec4 color;
varying float fog;
const int N = 2;
void main()
{
    vec3 n = normalize(gl_NormalMatrix * normal_in);
    vec4 c = vec4(0.0);
    for (int i = 0; i < N; ++i) {
        float d = max(dot(n, normalize(light[i])), 0.0);
        c += gl_FrontMaterial.diffuse * gl_LightSource[i].diffuse * d;
    }
    color = clamp(c, 0.0, 1.0);
    fog = length((gl_ModelViewMatrix * gl_Vertex).xyz);
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = mvp * gl_Vertex;
}
