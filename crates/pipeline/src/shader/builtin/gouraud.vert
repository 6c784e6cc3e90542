#version 330 core
// pipelens' Gouraud shading, the vertex half: the Blinn-Phong lighting of each vertex, once per
// vertex, with its own normal,
//   L = Σ k_a·c·I_a + Σ f_att·f_spot·(k_d·c·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p),
// sent to the fragment stage to be interpolated across the triangle (gouraud.frag). A textured
// surface is lit white here (c = 1); its texel modulates ambient and diffuse per pixel.
// pipelens declares these before your code (a program of your own declares them itself):
//   struct Light { int kind; vec3 position; vec3 direction; vec3 intensity;
//                  vec3 attenuation; float cutoff_cos; float exponent; };
//   const int LIGHT_AMBIENT = 0; const int LIGHT_POINT = 1;
//   const int LIGHT_DIRECTIONAL = 2; const int LIGHT_SPOT = 3; const int MAX_LIGHTS = 8;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform sampler2D displacement;    // displacement mapping's height map (none: black)
uniform float displacement_scale;  // its k (0 without one)
uniform mat3 normal_matrix;
uniform vec3 eye;
uniform vec3 ka;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;
uniform Light lights[MAX_LIGHTS];
uniform int light_count;
uniform bool use_tex;

in vec3 position;
in vec3 normal;
in vec2 uv;
in vec3 color;

out vec3 v_lit;        // ambient + diffuse
out vec3 v_specular;   // specular
out vec2 v_uv;

void main() {
    // Displacement mapping moves the vertex along its normal: p' = p + k·h(u, v)·n, h the
    // height map's luminance (bilinear, level 0).
    float h = dot(textureLod(displacement, uv, 0.0).rgb, vec3(0.2126, 0.7152, 0.0722));
    vec3 p_object = position + normal * (displacement_scale * h);
    vec4 world = model * vec4(p_object, 1.0);
    vec3 p = world.xyz;
    vec3 n = normalize(normal_matrix * normal);
    vec3 v = normalize(eye - p);
    vec3 c = use_tex ? vec3(1.0) : color;
    vec3 lit = vec3(0.0);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < light_count; i++) {
        Light light = lights[i];
        if (light.kind == LIGHT_AMBIENT) {
            lit += ka * c * light.intensity;
            continue;
        }
        vec3 l;
        float f = 1.0;
        if (light.kind == LIGHT_DIRECTIONAL) {
            l = normalize(-light.direction);
        } else {
            vec3 to_light = light.position - p;
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
        lit += f * kd * c * light.intensity * max(n_dot_l, 0.0);
        if (n_dot_l > 0.0) {
            specular += f * ks * light.intensity * pow(max(dot(n, h), 0.0), shininess);
        }
    }
    v_lit = lit;
    v_specular = specular;
    v_uv = uv;
    gl_Position = projection * (view * world);
}
