#version 330 core
// pipelens' own vertex stage as a shader: the position through M, V and P, and what the
// fragment stage interpolates (world position and normal, texture coordinates, colour).
uniform mat4 mvp;
uniform mat4 model;
uniform mat3 normal_matrix;

in vec3 position;
in vec3 normal;
in vec2 uv;
in vec3 color;

out vec3 w_pos;   // world position M·p
out vec3 w_nrm;   // world normal (M⁻¹)ᵀ·n, not yet normalized
out vec2 v_uv;
out vec3 v_color;

void main() {
    w_pos = (model * vec4(position, 1.0)).xyz;
    w_nrm = normal_matrix * normal;
    v_uv = uv;
    v_color = color;
    gl_Position = mvp * vec4(position, 1.0);
}
