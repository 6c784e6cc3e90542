#version 330 core
// GLSL's common and exponential built-ins on smooth inputs: smoothstep, clamp, mix, step,
// sign, abs, mod, fract, min, max, pow, exp, exp2, log, log2, sqrt, inversesqrt and the
// trigonometric functions, combined into a colour.
uniform vec3 eye;
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 v = normalize(eye - w_pos);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    float t = clamp(dot(n, v), 0.0, 1.0);
    float a = smoothstep(0.1, 0.9, d) * 0.5 + 0.25 * step(0.0, n.y) * abs(sign(n.x));
    float b = mix(exp(-2.0 * t), exp2(-t), 0.5) * sqrt(t + 0.01) + 0.1 * inversesqrt(1.0 + t);
    float c = 0.5 + 0.5 * sin(3.0 * n.x) * cos(2.0 * n.z) + 0.1 * atan(n.y, n.x + 2.0);
    float e = log(1.0 + d) / log(2.0) * 0.4 + 0.1 * log2(1.0 + t) + 0.1 * pow(t, 2.5);
    float f = min(max(mod(4.0 * d, 1.3), 0.1), 0.9) * 0.2 + 0.05 * fract(2.0 * t);
    color = vec4(a + 0.3 * e, b, c * 0.5 + f, 1.0);
}
