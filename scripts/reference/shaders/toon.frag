#version 330 core
// A toon shader: the diffuse term n·l quantised into four bands, a hard highlight, and a dark
// rim where the surface turns away from the eye.
uniform vec3 eye;
uniform vec3 light_pos;
uniform vec3 kd;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 l = normalize(light_pos - w_pos);
    vec3 v = normalize(eye - w_pos);
    float d = max(dot(n, l), 0.0);
    float band = floor(d * 4.0) / 4.0;
    vec3 c = kd * (0.2 + 0.8 * band);
    if (dot(reflect(-l, n), v) > 0.95) {
        c = vec3(1.0);
    }
    if (dot(n, v) < 0.2) {
        c *= 0.25;
    }
    color = vec4(c, 1.0);
}
