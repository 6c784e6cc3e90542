#version 330 core
// The object's texture read three ways and blended: textureOffset moves the lookup by whole
// texels of the level read (four texels right, two down), textureLodOffset reads level 2 one
// texel left, and textureProj divides the coordinates by their last component first.
uniform vec3 light_pos;
uniform sampler2D tex;

in vec3 w_pos;
in vec3 w_nrm;
in vec2 v_uv;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    vec3 l = normalize(light_pos - w_pos);
    vec3 a = textureOffset(tex, v_uv, ivec2(4, -2)).rgb;
    vec3 b = textureLodOffset(tex, v_uv, 2.0, ivec2(-1, 0)).rgb;
    float w = 1.5 + 0.5 * n.y;
    vec3 c = textureProj(tex, vec3(v_uv * w, w)).rgb;
    vec3 texel = 0.5 * a + 0.25 * b + 0.25 * c;
    color = vec4(texel * (0.2 + 0.8 * max(dot(n, l), 0.0)), 1.0);
}
