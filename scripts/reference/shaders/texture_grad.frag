#version 330 core
// textureGrad with the derivatives given: the quad's own dFdx and dFdy of the coordinates,
// scaled by 3 across and by 0.5 up and down (one level blurrier or sharper than texture()),
// and textureGradOffset three texels up. The level of detail comes from the derivatives
// given, not from the quad.
uniform vec3 light_pos;
uniform sampler2D tex;

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 l = normalize(light_pos - w_pos);
    vec2 dx = dFdx(v_uv);
    vec2 dy = dFdy(v_uv);
    vec3 blurred = textureGrad(tex, v_uv, dx * 3.0, dy * 3.0).rgb;
    vec3 sharp = textureGradOffset(tex, v_uv, dx * 0.5, dy * 0.5, ivec2(0, 3)).rgb;
    vec3 texel = n.x > 0.0 ? blurred : sharp;
    color = vec4(texel * (0.2 + 0.8 * max(dot(n, l), 0.0)), 1.0);
}
