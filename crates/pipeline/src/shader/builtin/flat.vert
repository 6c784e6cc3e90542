#version 330 core
// pipelens' flat shading, the vertex half: the vertex stage of pipelens.vert, and the values a
// face is lit with. OpenGL gives a `flat` output the provoking (last) vertex's value across the
// whole triangle: the face is lit at that vertex, with its colour.
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform sampler2D displacement;    // displacement mapping's height map (none: black)
uniform float displacement_scale;  // its k (0 without one)

in vec3 position;
in vec3 normal;
in vec2 uv;
in vec3 color;

out vec3 w_pos;           // world position, interpolated: its derivatives give the face normal
flat out vec3 f_pos;      // the provoking vertex's world position
flat out vec3 f_color;    // and its colour
out vec2 v_uv;

void main() {
    // Displacement mapping moves the vertex along its normal: p' = p + k·h(u, v)·n, h the
    // height map's luminance (bilinear, level 0).
    float h = dot(textureLod(displacement, uv, 0.0).rgb, vec3(0.2126, 0.7152, 0.0722));
    vec3 p_object = position + normal * (displacement_scale * h);
    vec4 world = model * vec4(p_object, 1.0);
    w_pos = world.xyz;
    f_pos = world.xyz;
    f_color = color;
    v_uv = uv;
    gl_Position = projection * (view * world);
}
