#version 330 core
// A procedural checkerboard with discard: every other 24-pixel square of the window is thrown
// away, so the far side of the mesh (or the background) shows through the holes. The squares
// are laid out on gl_FragCoord, whose pixel centres (x + 0.5, y + 0.5) are exact in any
// OpenGL: both renderers discard the very same fragments.
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec2 cell = floor(gl_FragCoord.xy / 24.0);
    if (mod(cell.x + cell.y, 2.0) > 0.5) {
        discard;
    }
    vec3 n = normalize(w_nrm);
    vec3 l = normalize(light_pos - w_pos);
    color = vec4(vec3(0.9, 0.6, 0.2) * (0.2 + 0.8 * abs(dot(n, l))), 1.0);
}
