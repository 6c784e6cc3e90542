#version 330 core
// Blinn-Phong with one white point light: L = k_a + k_d·I·max(n·l, 0) + k_s·I·max(n·h, 0)^p,
// h = normalize(l + v).
uniform vec3 eye;
uniform vec3 light_pos;
uniform vec3 light_color;
uniform vec3 ka;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 l = normalize(light_pos - w_pos);
    vec3 v = normalize(eye - w_pos);
    vec3 h = normalize(l + v);
    vec3 c = ka + kd * light_color * max(dot(n, l), 0.0)
           + ks * light_color * pow(max(dot(n, h), 0.0), shininess);
    color = vec4(c, 1.0);
}
