#version 330 core
// Functions as the course writes them: a prototype above main and the body below it,
// overloads by parameter type, an early return, and a function that calls another. Near the
// silhouette the colour passes white: a pixel there resolves the clamped samples (what a
// fixed-point colour buffer keeps), as OpenGL does.
uniform vec3 eye;
uniform vec3 light_pos;
uniform vec3 kd;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

float lambert(vec3 n, vec3 l);

float bias(float x) {
    return x * x * (3.0 - 2.0 * x);
}

vec3 bias(vec3 c) {
    return vec3(bias(c.r), bias(c.g), bias(c.b));
}

float rim(vec3 n, vec3 v) {
    float facing = dot(n, v);
    if (facing < 0.0) {
        return 0.0;
    }
    return pow(1.0 - facing, 3.0);
}

void main() {
    vec3 n = normalize(w_nrm);
    vec3 v = normalize(eye - w_pos);
    float d = lambert(n, normalize(light_pos - w_pos));
    vec3 c = bias(kd * (0.15 + 0.85 * d)) + vec3(0.2, 0.3, 0.6) * rim(n, v);
    color = vec4(c, 1.0);
}

float lambert(vec3 n, vec3 l) {
    return max(dot(n, l), 0.0);
}
