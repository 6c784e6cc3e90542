#version 330 core
// pipelens' Gouraud shading, the fragment half: the lighting of the three vertices arrives
// interpolated; a texel modulates the ambient and diffuse part (OpenGL's GL_MODULATE), the
// specular part is added on top.
uniform bool use_tex;
uniform sampler2D tex;

in vec3 v_lit;        // ambient + diffuse, lit with a white surface when textured
in vec3 v_specular;
in vec2 v_uv;

out vec4 color;

void main() {
    vec3 surface = use_tex ? texture(tex, v_uv).rgb : vec3(1.0);
    color = vec4(v_lit * surface + v_specular, 1.0);
}
