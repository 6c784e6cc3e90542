#version 330 core
// An array of light structs, filled in the shader: a loop over them with attenuation
// 1 / (1 + k·d²), a light skipped by `continue` when it is off, and Blinn-Phong per light.
uniform vec3 eye;
uniform vec3 light_pos;
uniform vec3 light_color;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

struct Light {
    vec3 position;
    vec3 color;
    float k;
    bool on;
};

vec3 shade(Light light, vec3 p, vec3 n, vec3 v) {
    vec3 to = light.position - p;
    float r2 = dot(to, to);
    vec3 l = to / sqrt(r2);
    vec3 h = normalize(l + v);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
    return light.color / (1.0 + light.k * r2) * (kd * diffuse + ks * specular);
}

void main() {
    Light lights[3];
    lights[0] = Light(light_pos, light_color, 0.02, true);
    lights[1] = Light(vec3(-3.0, 1.0, 2.0), vec3(0.3, 0.4, 0.9), 0.1, true);
    lights[2] = Light(vec3(0.0, -4.0, 0.0), vec3(1.0, 0.0, 0.0), 0.0, false);
    vec3 n = normalize(w_nrm);
    vec3 v = normalize(eye - w_pos);
    vec3 c = 0.05 * kd;
    for (int i = 0; i < lights.length(); ++i) {
        if (!lights[i].on) {
            continue;
        }
        c += shade(lights[i], w_pos, n, v);
    }
    color = vec4(c, 1.0);
}
