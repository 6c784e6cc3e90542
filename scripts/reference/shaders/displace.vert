#version 330 core
// A vertex shader that displaces: each vertex moves along its normal by a ripple of its
// height, 0.04·sin(12·y), before the model, view and projection matrices; the normal is
// passed on unchanged.
uniform mat4 mvp;
uniform mat4 model;
uniform mat3 normal_matrix;

in vec3 in_pos;
in vec3 in_nrm;
in vec2 in_uv;

out vec3 w_pos;
out vec3 w_nrm;
out vec2 v_uv;

void main() {
    vec3 n = normalize(in_nrm);
    vec3 p = in_pos + n * (0.04 * sin(12.0 * in_pos.y));
    w_pos = (model * vec4(p, 1.0)).xyz;
    w_nrm = normal_matrix * n;
    v_uv = in_uv;
    gl_Position = mvp * vec4(p, 1.0);
}
