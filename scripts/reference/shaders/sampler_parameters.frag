#version 330 core
// A sampler passed to functions (GLSL 3.30 §6.1): `look` reads the texture it is given,
// `blurred` asks its size and passes it on, three times, to `look`.
uniform vec3 light_pos;
uniform sampler2D tex;

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;

out vec4 color;

vec3 look(sampler2D s, vec2 at) {
    return texture(s, at).rgb;
}

vec3 blurred(sampler2D s, vec2 at) {
    vec2 texel = 1.0 / vec2(textureSize(s, 0));
    return 0.5 * look(s, at)
        + 0.25 * look(s, at + vec2(3.0 * texel.x, 0.0))
        + 0.25 * look(s, at - vec2(0.0, 3.0 * texel.y));
}

void main() {
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    color = vec4(blurred(tex, v_uv) * (0.2 + 0.8 * d), 1.0);
}
