#version 330 core
// The vertex shader of the reference check's lit cases: world position and normal for the
// fragment stage, texture coordinates, and the clip position MVP·p. The attribute names are the
// llvmpipe peer's (in_pos, in_nrm, in_uv); pipelens reads them as position, normal and uv.
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
    w_pos = (model * vec4(in_pos, 1.0)).xyz;
    w_nrm = normal_matrix * in_nrm;
    v_uv = in_uv;
    gl_Position = mvp * vec4(in_pos, 1.0);
}
