#version 330 core
// The object's texture through texture(): the mip level comes from the derivatives of v_uv over
// the 2×2 quad, so a minified texture is filtered trilinearly. Lit diffusely.
uniform vec3 light_pos;
uniform sampler2D tex;

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 l = normalize(light_pos - w_pos);
    vec3 texel = texture(tex, v_uv).rgb;
    color = vec4(texel * (0.2 + 0.8 * max(dot(n, l), 0.0)), 1.0);
}
