#version 330 core
// pipelens' own vertex stage as a shader: the position through M, V and P one matrix at a
// time (model → world → eye → clip, in the order the vertex table shows them), and what the
// fragment stage interpolates (world position, unit world normal, texture coordinates, colour).
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normal_matrix;

in vec3 position;
in vec3 normal;
in vec2 uv;
in vec3 color;

out vec3 w_pos;   // world position M·p
out vec3 w_nrm;   // world normal (M⁻¹)ᵀ·n, normalized (interpolation shortens it again)
out vec2 v_uv;
out vec3 v_color;

void main() {
    vec4 world = model * vec4(position, 1.0);
    w_pos = world.xyz;
    w_nrm = normalize(normal_matrix * normal);
    v_uv = uv;
    v_color = color;
    gl_Position = projection * (view * world);
}
