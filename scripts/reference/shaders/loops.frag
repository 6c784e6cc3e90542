#version 330 core
// Loops of every form: a while loop that halves until small, a do-while, nested for loops with
// break and continue, and a loop whose bound comes from the fragment.
uniform vec3 light_pos;

in vec3 w_pos;
in vec3 w_nrm;

out vec4 color;

void main() {
    vec3 n = normalize(w_nrm);
    float d = max(dot(n, normalize(light_pos - w_pos)), 0.0);
    float x = 1.0 + 20.0 * d;
    int halvings = 0;
    while (x > 1.0) {
        x *= 0.5;
        halvings++;
    }
    float sum = 0.0;
    int k = 0;
    do {
        sum += 1.0 / float(k + 1);
        k++;
    } while (k < 4);
    float grid = 0.0;
    for (int i = 0; i < 4; i++) {
        if (i == 2) {
            continue;
        }
        for (int j = 0; j < 4; j++) {
            if (j > i) {
                break;
            }
            grid += 0.05;
        }
    }
    int steps = int(n.y * 4.0 + 4.0);
    float ramp = 0.0;
    for (int i = 0; i < steps; i++) {
        ramp += 0.1;
    }
    color = vec4(float(halvings) / 6.0, sum / 3.0 * d, grid + 0.2 * ramp * d, 1.0);
}
