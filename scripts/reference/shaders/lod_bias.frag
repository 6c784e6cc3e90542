#version 330 core
// The level of detail moved by hand: texture() with a bias of 1.5 (a blurrier level than the
// footprint asks for) and textureLod at a level from the lighting, blended.
uniform vec3 light_pos;
uniform sampler2D tex;

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    vec3 biased = texture(tex, v_uv, 1.5).rgb;
    vec3 chosen = textureLod(tex, v_uv, 4.0 * (1.0 - d)).rgb;
    color = vec4(mix(biased, chosen, 0.5) * (0.2 + 0.8 * d), 1.0);
}
