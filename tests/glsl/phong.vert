// The vertex half of the 200-line shader pair that times the first draw with a new
// program (issue #20): per-vertex set-up for per-fragment Phong lighting with fog and a
// texture matrix.
#version 120

uniform mat4 modelView;
uniform mat4 projection;
uniform mat3 normalMatrix;
uniform mat4 textureMatrix;
uniform float time;
uniform float waveAmplitude;
uniform vec3 waveDirection;
uniform bool animate;
uniform int fogMode;
uniform float fogDensity;

attribute vec4 position;
attribute vec3 normal;
attribute vec2 texCoord;
attribute vec4 tangent;

varying vec3 eyePosition;
varying vec3 eyeNormal;
varying vec3 eyeTangent;
varying vec3 eyeBitangent;
varying vec2 uv;
varying float fogFactor;
varying vec4 vertexColor;

const float PI = 3.14159265;

float wave(vec3 p, float t)
{
    float phase = dot(p, normalize(waveDirection)) * 2.0 * PI;
    float sum = 0.0;
    for (int octave = 0; octave < 3; ++octave) {
        float k = float(octave + 1);
        sum += sin(phase * k + t * k) / k;
    }
    return sum * waveAmplitude;
}

vec3 waveNormal(vec3 p, vec3 n, float t)
{
    float e = 0.01;
    float dx = wave(p + vec3(e, 0.0, 0.0), t) - wave(p - vec3(e, 0.0, 0.0), t);
    float dz = wave(p + vec3(0.0, 0.0, e), t) - wave(p - vec3(0.0, 0.0, e), t);
    return normalize(n + vec3(-dx, 0.0, -dz) / (2.0 * e));
}

float computeFog(float distance)
{
    float f = 1.0;
    if (fogMode == 1) {
        f = exp(-fogDensity * distance);
    } else if (fogMode == 2) {
        float d = fogDensity * distance;
        f = exp(-d * d);
    } else if (fogMode == 3) {
        f = (gl_Fog.end - distance) * gl_Fog.scale;
    }
    return clamp(f, 0.0, 1.0);
}

void main()
{
    vec4 p = position;
    vec3 n = normal;
    if (animate) {
        p.y += wave(p.xyz, time);
        n = waveNormal(p.xyz, n, time);
    }
    vec4 eye = modelView * p;
    eyePosition = eye.xyz / eye.w;
    eyeNormal = normalize(normalMatrix * n);
    eyeTangent = normalize(normalMatrix * tangent.xyz);
    eyeBitangent = cross(eyeNormal, eyeTangent) * tangent.w;
    uv = (textureMatrix * vec4(texCoord, 0.0, 1.0)).st;
    fogFactor = computeFog(length(eyePosition));
    vertexColor = gl_Color;
    gl_Position = projection * eye;
}
