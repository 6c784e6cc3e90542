#version 330 core
// Integer and bit operations on the window position: an XOR pattern of 8-pixel cells (^, &,
// >>), a shifted mask (<<, |), unsigned arithmetic with wrap-around, ivec2 % int and integer
// division, each exact in any OpenGL because gl_FragCoord's centres are.
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 cell = p >> 3;
    int x = (cell.x ^ cell.y) & 7;
    int mask = (1 << (cell.x % 5)) | 0x10;
    uint h = uint(p.x) * 2654435761u + uint(p.y);
    h = (h ^ (h >> 13u)) * 1274126177u;
    ivec2 m = p % 16;
    int q = (p.x - p.y) / 7;
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    vec3 c = vec3(float(x) / 7.0, float(mask & 0x13) / 19.0, float(h >> 28u) / 15.0);
    c = mix(c, vec3(float(m.x + m.y) / 30.0, float(abs(q) % 9) / 8.0, 0.5), 0.3);
    color = vec4(c * (0.3 + 0.7 * d), 1.0);
}
