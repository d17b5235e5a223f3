uniform float limit;
float f(float x)
{
    float y = 0.0;
    do {
        y += x;
        if (y > limit)
            return y;
    } while (y < 100.0);
    return -y;
}
void main()
{
    int n = 0;
    while (true) {
        n++;
        if (n > 10) break;
        if (mod(float(n), 2.0) == 0.0) continue;
    }
    gl_FragColor = vec4(f(float(n)), gl_FragCoord.xy, gl_FrontFacing ? 1.0 : 0.0);
}
