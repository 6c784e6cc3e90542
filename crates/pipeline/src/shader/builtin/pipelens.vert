#version 330 core
// pipelens' own vertex stage as a shader: the position (displaced, with a displacement map)
// through M, V and P one matrix at a time (model → world → eye → clip, in the order the vertex
// table shows them), and what the fragment stage interpolates (world position, unit world normal, texture coordinates, colour).
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform sampler2D displacement;    // displacement mapping's height map (none: black)
uniform float displacement_scale;  // its k (0 without one)
uniform mat3 normal_matrix;

in vec3 position;
in vec3 normal;
in vec2 uv;
in vec3 color;

out vec3 w_pos;   // world position M·p
out vec3 w_nrm;   // world normal (M⁻¹)^T·n, normalized (interpolation shortens it again)
out vec2 v_uv;
out vec3 v_color;

void main() {
    // Displacement mapping moves the vertex along its normal: p' = p + k·h(u, v)·n, h the
    // height map's luminance (bilinear, level 0).
    float h = dot(textureLod(displacement, uv, 0.0).rgb, vec3(0.2126, 0.7152, 0.0722));
    vec3 p_object = position + normal * (displacement_scale * h);
    vec4 world = model * vec4(p_object, 1.0);
    w_pos = world.xyz;
    w_nrm = normalize(normal_matrix * normal);
    v_uv = uv;
    v_color = color;
    gl_Position = projection * (view * world);
}
