#version 330 core
// A switch on a band of the window: cases that fall through, a default, and a break inside a
// loop within a case. Each band's colour is lit diffusely.
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    int band = int(gl_FragCoord.x) / 40 % 6;
    vec3 c = vec3(0.0);
    switch (band) {
        case 0:
            c = vec3(0.9, 0.2, 0.2);
            break;
        case 1:
            c.g = 0.5;
            // falls through into case 2
        case 2:
            c.r += 0.3;
            c.b = 0.6;
            break;
        case 4: {
            for (int i = 0; i < 10; i++) {
                c += vec3(0.1, 0.08, 0.02);
                if (i == 5) {
                    break;
                }
            }
            break;
        }
        default:
            c = vec3(0.2, 0.7, 0.9);
    }
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    color = vec4(c * (0.25 + 0.75 * d), 1.0);
}
