// The fragment half of the 200-line shader pair (see phong.vert): Phong lighting from
// four lights of three kinds, a normal map, a diffuse texture, a specular map, rim
// lighting, tone mapping and fog.
#version 120

const int LIGHTS = 4;

struct Light {
    vec4 position;
    vec3 color;
    vec3 direction;
    float cutoff;
    float exponent;
    vec3 attenuation;
};

struct Material {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float shininess;
    float rim;
};

uniform Light lights[LIGHTS];
uniform int lightCount;
uniform Material material;
uniform sampler2D diffuseMap;
uniform sampler2D normalMap;
uniform sampler2D specularMap;
uniform vec3 ambientColor;
uniform vec3 fogColor;
uniform float exposure;
uniform float gamma;
uniform bool useNormalMap;
uniform bool toneMap;

varying vec3 eyePosition;
varying vec3 eyeNormal;
varying vec3 eyeTangent;
varying vec3 eyeBitangent;
varying vec2 uv;
varying float fogFactor;
varying vec4 vertexColor;

float attenuation(Light light, float distance)
{
    vec3 k = light.attenuation;
    return 1.0 / (k.x + k.y * distance + k.z * distance * distance);
}

float spotFactor(Light light, vec3 toLight)
{
    if (light.cutoff >= 180.0)
        return 1.0;
    float cosine = dot(-toLight, normalize(light.direction));
    if (cosine < cos(radians(light.cutoff)))
        return 0.0;
    return pow(max(cosine, 0.0), light.exponent);
}

vec3 perturbedNormal(vec3 n)
{
    if (!useNormalMap)
        return normalize(n);
    vec3 t = normalize(eyeTangent);
    vec3 b = normalize(eyeBitangent);
    vec3 m = texture2D(normalMap, uv).xyz * 2.0 - 1.0;
    mat3 tbn = mat3(t, b, normalize(n));
    return normalize(tbn * m);
}

void shade(Light light, vec3 n, vec3 v, float shininess, inout vec3 diffuse, inout vec3 specular)
{
    vec3 toLight;
    float falloff = 1.0;
    if (light.position.w == 0.0) {
        toLight = normalize(light.position.xyz);
    } else {
        vec3 d = light.position.xyz - eyePosition;
        float distance = length(d);
        toLight = d / distance;
        falloff = attenuation(light, distance) * spotFactor(light, toLight);
    }
    float nDotL = max(dot(n, toLight), 0.0);
    if (nDotL <= 0.0 || falloff <= 0.0)
        return;
    diffuse += light.color * nDotL * falloff;
    vec3 h = normalize(toLight + v);
    float nDotH = max(dot(n, h), 0.0);
    specular += light.color * pow(nDotH, shininess) * falloff;
}

vec3 toneMapped(vec3 c)
{
    if (!toneMap)
        return clamp(c, 0.0, 1.0);
    vec3 mapped = vec3(1.0) - exp(-c * exposure);
    return pow(mapped, vec3(1.0 / gamma));
}

float rimLight(vec3 n, vec3 v)
{
    float r = 1.0 - max(dot(n, v), 0.0);
    return smoothstep(0.6, 1.0, r) * material.rim;
}

vec3 checker(vec2 p)
{
    vec2 cell = floor(p * 8.0);
    float odd = mod(cell.x + cell.y, 2.0);
    return mix(vec3(0.8), vec3(1.0), odd);
}

void main()
{
    vec3 n = perturbedNormal(eyeNormal);
    if (!gl_FrontFacing)
        n = -n;
    vec3 v = normalize(-eyePosition);
    vec4 base = texture2D(diffuseMap, uv) * vertexColor;
    if (base.a < 0.01)
        discard;
    vec3 specularTint = texture2D(specularMap, uv).rgb;
    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < LIGHTS; i++) {
        if (i >= lightCount)
            break;
        shade(lights[i], n, v, material.shininess, diffuse, specular);
    }
    vec3 albedo = base.rgb * checker(uv);
    vec3 color = ambientColor * material.ambient * albedo;
    color += diffuse * material.diffuse * albedo;
    color += specular * material.specular * specularTint;
    color += rimLight(n, v) * diffuse;
    color = toneMapped(color);
    color = mix(fogColor, color, fogFactor);
    gl_FragColor = vec4(color, base.a);
}
