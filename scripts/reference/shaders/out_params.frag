#version 330 core
// Functions with `out` and `inout` parameters (GLSL 3.30 §6.1.1): one call returns the diffuse
// and specular terms through two `out` floats, another tones the colour in place through an
// `inout` vec3, a third writes a component of a vector and an array element.
uniform vec3 eye;
uniform vec3 light_pos;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void blinn_phong_terms(vec3 n, vec3 l, vec3 v, out float diffuse, out float specular) {
    vec3 h = normalize(l + v);
    diffuse = max(dot(n, l), 0.0);
    specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
}

void tone(inout vec3 c, in float exposure) {
    c = vec3(1.0) - exp(-c * exposure);
}

void split(float x, out float whole, out float part) {
    whole = floor(x);
    part = x - whole;
}

void main() {
    vec3 n = normalize(w_nrm);
    vec3 l = normalize(light_pos - w_pos);
    vec3 v = normalize(eye - w_pos);
    float d;
    float s;
    blinn_phong_terms(n, l, v, d, s);
    vec3 c = 0.1 * kd + kd * d + ks * s;
    tone(c, 1.5);
    vec2 parts;
    float bands[2];
    split(d * 3.0, bands[1], parts.y);
    c.b = mix(c.b, 0.25 * bands[1] + 0.2 * parts.y, 0.5);
    color = vec4(c, 1.0);
}
