#version 330 core
// texelFetch and textureSize: the texel under the coordinates read by its integer address in
// level 1 (no filtering), beside texture() of the same place.
uniform vec3 light_pos;
uniform sampler2D tex;

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;

out vec4 color;

void main() {
    ivec2 size = textureSize(tex, 1);
    ivec2 ij = ivec2(fract(v_uv) * vec2(size));
    vec3 texel = texelFetch(tex, ij, 1).rgb;
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    color = vec4(texel * (0.2 + 0.8 * d), 1.0);
}
