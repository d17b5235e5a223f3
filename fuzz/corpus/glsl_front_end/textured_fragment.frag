#version 110
uniform sampler2D tex;
uniform sampler2DShadow depth;
uniform vec4 tint;
varying vec4 color;
void main()
{
    vec4 t = texture2D(tex, gl_TexCoord[0].st, 0.5);
    float lit = shadow2DProj(depth, gl_TexCoord[1]).r;
    if (t.a < 0.1)
        discard;
    gl_FragColor = mix(color * t, tint, lit) + vec4(dFdx(t.r), dFdy(t.g), 0.0, 0.0);
}
