#version 330 core
// The interpolation qualifiers side by side: the same value sent smooth (perspective-correct),
// noperspective (affine in the window) and flat (the provoking vertex's, the last one).
uniform mat4 mvp;

in vec3 in_pos;
in vec3 in_nrm;

out vec3 v_smooth;
noperspective out vec3 v_affine;
flat out vec3 v_flat;

void main() {
    vec3 c = in_nrm * 0.5 + 0.5;
    v_smooth = c;
    v_affine = c;
    v_flat = c;
    gl_Position = mvp * vec4(in_pos, 1.0);
}
