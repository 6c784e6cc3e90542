#version 330 core
// pipelens' unlit shading as a shader: the surface colour as it is, the texel where the object
// is textured, else the vertex colour (interpolated).
uniform bool use_tex;
uniform sampler2D tex;

in vec2 v_uv;
in vec3 v_color;

out vec4 color;

void main() {
    color = vec4(use_tex ? texture(tex, v_uv).rgb : v_color, 1.0);
}
