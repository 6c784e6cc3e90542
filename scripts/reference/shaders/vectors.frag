#version 330 core
// Vector relational functions and bool vectors: lessThan, greaterThanEqual, equal, any, all,
// not, and mix by a bvec; writes through swizzles.
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    bvec3 up = greaterThanEqual(n, vec3(0.0));
    bvec3 small = lessThan(abs(n), vec3(0.5));
    vec3 c = mix(vec3(0.2, 0.3, 0.4), vec3(0.9, 0.7, 0.3), up);
    if (any(small) && !all(small)) {
        c.zx = c.xz * 0.8;
    }
    bvec2 same = equal(ivec2(up.xy), ivec2(1, 1));
    if (all(not(same))) {
        c.g += 0.2;
    }
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    color = vec4(c * (0.3 + 0.7 * d), 1.0);
}
