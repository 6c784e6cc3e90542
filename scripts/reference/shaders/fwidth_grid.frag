#version 330 core
// A grid of lines a constant width on screen, from the derivatives of the world position
// (fwidth = |dFdx| + |dFdy|): the course's derivative-based pattern, anti-aliased by its own
// footprint rather than by extra samples.
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec3 p = w_pos * 8.0;
    vec3 grid = abs(fract(p - 0.5) - 0.5) / max(fwidth(p), vec3(1e-4));
    float line = min(min(grid.x, grid.y), grid.z);
    float ink = 1.0 - min(line, 1.0);
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    vec3 base = vec3(0.85, 0.8, 0.7) * (0.25 + 0.75 * d);
    color = vec4(mix(base, vec3(0.1, 0.2, 0.5), ink), 1.0);
}
