#version 120
struct Light { vec3 dir; float power[3]; };
uniform Light lights[3];
uniform int count;
float sum(in float a[3]) { return a[0] + a[1] + a[2]; }
void accumulate(inout vec3 total, const in Light l) { total += l.dir * sum(l.power); }
void main()
{
    vec3 total = vec3(0.0);
    for (int i = 0; i < 3; i++) {
        if (i >= count) break;
        accumulate(total, lights[i]);
    }
    float w[2] = float[2](0.25, 0.75);
    mat2x3 m = mat2x3(total, total.zyx);
    gl_FragData[0] = vec4(m * vec2(w[0], w[1]), float(w.length()));
}
