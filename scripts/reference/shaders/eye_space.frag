#version 330 core
// Phong in eye space: the eye is at the origin, so v = −p; the light's world position is
// carried into eye space by the view matrix.
uniform mat4 view;
uniform vec3 light_pos;
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;

in vec3 e_pos;
in vec3 e_nrm;

out vec4 color;

void main() {
    vec3 n = normalize(e_nrm);
    vec3 light = (view * vec4(light_pos, 1.0)).xyz;
    vec3 l = normalize(light - e_pos);
    vec3 v = normalize(-e_pos);
    vec3 r = reflect(-l, n);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(r, v), 0.0), shininess) : 0.0;
    color = vec4(0.05 * kd + kd * diffuse + ks * specular, 1.0);
}
