#version 330 core
// Phong's own specular term: the mirror direction r = reflect(−l, n) = 2(n·l)n − l against the
// view direction, k_s·I·max(r·v, 0)^p (a smaller highlight than Blinn-Phong's at the same p).
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
    vec3 r = reflect(-l, n);
    float spec = dot(n, l) > 0.0 ? pow(max(dot(r, v), 0.0), shininess) : 0.0;
    vec3 c = ka + kd * light_color * max(dot(n, l), 0.0) + ks * light_color * spec;
    color = vec4(c, 1.0);
}
