#version 330 core
// Arrays indexed at run time: a palette of five colours chosen by the diffuse term, read
// between two neighbouring entries, and an array filled in a loop and summed back.
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

const vec3 PALETTE[5] = vec3[5](
    vec3(0.10, 0.05, 0.20),
    vec3(0.35, 0.10, 0.40),
    vec3(0.80, 0.25, 0.30),
    vec3(0.95, 0.60, 0.20),
    vec3(1.00, 0.95, 0.70)
);

void main() {
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    float x = d * 3.999;
    int i = int(x);
    vec3 c = mix(PALETTE[i], PALETTE[i + 1], x - float(i));
    float weights[4];
    for (int k = 0; k < 4; k++) {
        weights[k] = float(k + 1) * 0.1;
    }
    float w = 0.0;
    for (int k = 0; k < weights.length(); k++) {
        w += weights[k];
    }
    color = vec4(c * w, 1.0);
}
