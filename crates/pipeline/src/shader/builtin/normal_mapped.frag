#version 330 core
// pipelens' per-pixel Blinn-Phong lighting (blinn_phong.frag) with a bump or normal map: the
// interpolated normal n is tilted in the tangent frame before lighting.
//   Tangent frame: T = ∂p/∂u, B = ∂p/∂v. The screen derivatives of p and uv obey
//     dFdx(p) = T·dFdx(u) + B·dFdx(v),  dFdy(p) = T·dFdy(u) + B·dFdy(v),
//   two equations solved for T and B (the same T, B as from the triangle's edges).
//   T' = normalize(T − n(n·T)), B' = ±n×T' (the sign of B), n' = normalize(T'·x + B'·y + n·z):
//   bump map (GAMES101): (x, y, z) = (−dU, −dV, 1), dU = k_h·k_n·(h(u + 1/w, v) − h(u, v)),
//                        dV = k_h·k_n·(h(u, v + 1/h) − h(u, v)), h the texel's luminance;
//   normal map:          (x, y, z) = 2·texel − 1.
// pipelens declares these before your code (a program of your own declares them itself):
//   struct Light { int kind; vec3 position; vec3 direction; vec3 intensity;
//                  vec3 attenuation; float cutoff_cos; float exponent; };
//   const int LIGHT_AMBIENT = 0; const int LIGHT_POINT = 1;
//   const int LIGHT_DIRECTIONAL = 2; const int LIGHT_SPOT = 3; const int MAX_LIGHTS = 8;
uniform vec3 eye;
uniform vec3 ka;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;
uniform Light lights[MAX_LIGHTS];
uniform int light_count;
uniform bool use_tex;
uniform sampler2D tex;
uniform int detail_kind;        // 0 none, 1 bump map, 2 normal map
uniform float bump_strength;    // k_h·k_n
uniform sampler2D detail;       // the height or normal map: bilinear, repeating, level 0

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;
in vec3 v_color;

out vec4 color;

// The luminance of the height map at uv: h(u, v).
float height(vec2 uv) {
    return dot(textureLod(detail, uv, 0.0).rgb, vec3(0.2126, 0.7152, 0.0722));
}

// n tilted by the bump or normal map at uv.
vec3 perturb(vec3 n, vec2 uv) {
    vec3 dpx = dFdx(w_pos);
    vec3 dpy = dFdy(w_pos);
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    float det = dx.x * dy.y - dy.x * dx.y;
    if (det == 0.0) {
        return n;   // the uvs do not grow across this triangle: no frame
    }
    vec3 t = (dpx * dy.y - dpy * dx.y) / det;
    vec3 b = (dpy * dx.x - dpx * dy.x) / det;
    vec3 t1 = normalize(t - n * dot(n, t));
    vec3 b1 = cross(n, t1) * (dot(cross(n, t1), b) < 0.0 ? -1.0 : 1.0);
    vec3 local;
    if (detail_kind == 1) {
        vec2 size = vec2(textureSize(detail, 0));
        float here = height(uv);
        float du = bump_strength * (height(uv + vec2(1.0 / size.x, 0.0)) - here);
        float dv = bump_strength * (height(uv + vec2(0.0, 1.0 / size.y)) - here);
        local = vec3(-du, -dv, 1.0);
    } else {
        local = textureLod(detail, uv, 0.0).rgb * 2.0 - 1.0;
    }
    return normalize(t1 * local.x + b1 * local.y + n * local.z);
}

void main() {
    vec3 n = normalize(w_nrm);
    if (detail_kind != 0) {
        n = perturb(n, v_uv);
    }
    vec3 v = normalize(eye - w_pos);
    vec3 c = use_tex ? texture(tex, v_uv).rgb : v_color;   // the surface colour
    vec3 sum = vec3(0.0);
    for (int i = 0; i < light_count; i++) {
        Light light = lights[i];
        if (light.kind == LIGHT_AMBIENT) {
            sum += ka * c * light.intensity;
            continue;
        }
        vec3 l;
        float f = 1.0;
        if (light.kind == LIGHT_DIRECTIONAL) {
            l = normalize(-light.direction);
        } else {
            vec3 to_light = light.position - w_pos;
            float d = length(to_light);
            l = normalize(to_light);
            vec3 abc = light.attenuation;
            float denom = abc.x + abc.y * d + abc.z * d * d;
            if (denom > 0.0) {
                f = 1.0 / denom;
            }
            if (light.kind == LIGHT_SPOT) {
                float cos_phi = dot(-l, normalize(light.direction));
                f *= cos_phi < light.cutoff_cos ? 0.0 : pow(max(cos_phi, 0.0), light.exponent);
            }
        }
        float n_dot_l = dot(n, l);
        vec3 h = normalize(l + v);
        sum += f * kd * c * light.intensity * max(n_dot_l, 0.0);
        if (n_dot_l > 0.0) {
            sum += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }
    }
    color = vec4(sum, 1.0);
}
