#version 330 core
// pipelens' per-pixel Blinn-Phong lighting of a mirror (environment mapping), as a shader:
//   L = (1 − k)·(ambient + diffuse) + specular + k·env(r),   r = 2(n·v)n − v = reflect(−v, n)
// with ambient = Σ k_a·c·I_a, diffuse = Σ f_att·f_spot·k_d·c·I·max(n·l, 0),
// specular = Σ f_att·f_spot·k_s·I·max(n·h, 0)^p, env(r) the cube map seen in direction r and
// k the reflectivity: a mirror shows k of what it reflects and keeps 1 − k of its own light.
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
uniform samplerCube environment;   // the surroundings: +x, −x, +y, −y, +z, −z
uniform float reflectivity;        // k

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;
in vec3 v_color;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 v = normalize(eye - w_pos);
    vec3 c = use_tex ? texture(tex, v_uv).rgb : v_color;   // the surface colour
    vec3 own = vec3(0.0);        // ambient + diffuse
    vec3 specular = vec3(0.0);
    for (int i = 0; i < light_count; i++) {
        Light light = lights[i];
        if (light.kind == LIGHT_AMBIENT) {
            own += ka * c * light.intensity;
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
        own += f * kd * c * light.intensity * max(n_dot_l, 0.0);
        if (n_dot_l > 0.0) {
            specular += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }
    }
    vec3 r = reflect(-v, n);                         // the mirror direction 2(n·v)n − v
    vec3 reflected = texture(environment, r).rgb;    // env(r)
    float k = clamp(reflectivity, 0.0, 1.0);
    color = vec4((1.0 - k) * own + specular + k * reflected, 1.0);
}
