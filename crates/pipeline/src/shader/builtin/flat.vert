#version 330 core
// pipelens' flat shading, the vertex half: the vertex stage of pipelens.vert, and the values a
// face is lit with. OpenGL gives a `flat` output the provoking (last) vertex's value across the
// whole triangle: the face is lit at that vertex, with its colour.
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

in vec3 position;
in vec2 uv;
in vec3 color;

out vec3 w_pos;           // world position, interpolated: its derivatives give the face normal
flat out vec3 f_pos;      // the provoking vertex's world position
flat out vec3 f_color;    // and its colour
out vec2 v_uv;

void main() {
    vec4 world = model * vec4(position, 1.0);
    w_pos = world.xyz;
    f_pos = world.xyz;
    f_color = color;
    v_uv = uv;
    gl_Position = projection * (view * world);
}
