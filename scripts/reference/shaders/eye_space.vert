#version 330 core
// The OpenGL course's way: lighting in eye space. The vertex goes through the model-view
// matrix V·M and then the projection P; its normal through the inverse transpose of V·M's
// upper 3×3, computed here.
uniform mat4 model_view;
uniform mat4 projection;

in vec3 in_pos;
in vec3 in_nrm;

out vec3 e_pos;
out vec3 e_nrm;

void main() {
    vec4 p = model_view * vec4(in_pos, 1.0);
    mat3 normal_eye = transpose(inverse(mat3(model_view)));
    e_pos = p.xyz;
    e_nrm = normal_eye * in_nrm;
    gl_Position = projection * p;
}
