#version 330 core
// pipelens' flat shading, the fragment half: one normal per face and one lighting per face.
// The face normal is the cross product of two directions in the face's plane: as x and y move
// on the screen the world position p moves within the face, so ∂p/∂x and ∂p/∂y are two such
// directions and n_face = ±normalize(dFdx(p) × dFdy(p)), + for a front face. (Only the
// direction holds in general: (p1 − p0)×(p2 − p0) = 2·area·(∂p/∂x × ∂p/∂y) holds for an affine
// mapping alone, not under perspective.)
// The Blinn-Phong lighting is that of gouraud.vert, at the provoking vertex f_pos: every
// fragment of the face computes the same colour. A textured surface is lit white (c = 1) and
// its texel modulates ambient and diffuse, as with Gouraud shading.
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

in vec3 w_pos;
flat in vec3 f_pos;
flat in vec3 f_color;
in vec2 v_uv;

out vec4 color;

void main() {
    vec3 across = cross(dFdx(w_pos), dFdy(w_pos));
    vec3 n = normalize(gl_FrontFacing ? across : -across);
    vec3 p = f_pos;
    vec3 v = normalize(eye - p);
    vec3 c = use_tex ? vec3(1.0) : f_color;
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
    vec3 surface = use_tex ? texture(tex, v_uv).rgb : vec3(1.0);
    color = vec4(lit * surface + specular, 1.0);
}
